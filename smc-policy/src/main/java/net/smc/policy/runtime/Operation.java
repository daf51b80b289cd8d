package net.smc.policy.runtime;

import net.smc.policy.api.OpContext;

import net.smc.policy.api.PonderError;
import java.lang.invoke.MethodHandle;
import java.lang.invoke.MethodHandles;
import java.lang.invoke.MethodType;
import java.lang.reflect.Constructor;
import java.lang.reflect.Executable;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.util.Arrays;
import java.util.List;

/**
 * One entry of a dispatch table: a selector bound to a Java method or constructor, with its
 * argument converters. Built once per class; invoked through a method handle of one generic shape,
 * {@code (context, receiver, args...) -> result}.
 */
final class Operation {
    /** How the receiver is passed. */
    enum Kind { INSTANCE, STATIC_RECEIVER, FACTORY }

    private static final MethodHandles.Lookup LOOKUP = MethodHandles.lookup();

    final String selector;
    final int arity;
    final Kind kind;
    private final MethodHandle handle;
    private final Converter[] converters;
    private final boolean returnsVoid;
    private final boolean wantsContext;
    private final String owner;

    private Operation(String selector, int arity, Kind kind, MethodHandle handle, Converter[] converters, boolean returnsVoid,
                      boolean wantsContext, String owner) {
        this.selector = selector;
        this.arity = arity;
        this.kind = kind;
        this.handle = handle;
        this.converters = converters;
        this.returnsVoid = returnsVoid;
        this.wantsContext = wantsContext;
        this.owner = owner;
    }

    /** The number of arguments a selector takes: 0 unary, 1 binary, one per colon for keywords. */
    static int arityOf(String selector) {
        if (selector.isEmpty()) {
            throw new IllegalArgumentException("empty selector");
        }
        char first = selector.charAt(0);
        if (!Character.isLetter(first)) {
            return 1;
        }
        int colons = 0;
        for (int i = 0; i < selector.length(); i++) {
            if (selector.charAt(i) == ':') {
                colons++;
            }
        }
        return colons;
    }

    static Operation of(String selector, Executable member, Kind kind, String owner) {
        Class<?>[] params = member.getParameterTypes();
        boolean wantsContext = params.length > 0 && (params[0] == CallContext.class || params[0] == OpContext.class);
        int skip = (wantsContext ? 1 : 0) + (kind == Kind.STATIC_RECEIVER ? 1 : 0);
        int arity = params.length - skip;
        int expected = arityOf(selector);
        if (arity != expected) {
            throw new IllegalArgumentException("operation '" + selector + "' of " + owner + " (" + member
                    + ") takes " + arity + " arguments; the selector needs " + expected);
        }
        Converter[] converters = new Converter[arity];
        for (int i = 0; i < arity; i++) {
            converters[i] = Converter.forType(params[skip + i], i + 1, selector, owner);
        }
        boolean returnsVoid = member instanceof Method m && m.getReturnType() == void.class;
        MethodHandle mh = generic(member, kind, wantsContext, arity);
        return new Operation(selector, arity, kind, mh, converters, returnsVoid, wantsContext, owner);
    }

    /** Adapts the member to {@code (Object context, Object receiver, Object... args) Object}. */
    private static MethodHandle generic(Executable member, Kind kind, boolean wantsContext, int arity) {
        try {
            member.setAccessible(true);
            MethodHandle mh = member instanceof Method m ? LOOKUP.unreflect(m) : LOOKUP.unreflectConstructor((Constructor<?>) member);
            boolean isStatic = member instanceof Constructor<?> || Modifier.isStatic(member.getModifiers());
            switch (kind) {
                case INSTANCE -> {
                    if (isStatic) {
                        throw new IllegalArgumentException(member + " must be an instance method");
                    }
                    if (wantsContext) {
                        MethodType t = mh.type();
                        MethodType swapped = t.changeParameterType(0, t.parameterType(1)).changeParameterType(1, t.parameterType(0));
                        int[] order = new int[t.parameterCount()];
                        order[0] = 1;
                        order[1] = 0;
                        for (int i = 2; i < order.length; i++) {
                            order[i] = i;
                        }
                        mh = MethodHandles.permuteArguments(mh, swapped, order);
                    } else {
                        mh = MethodHandles.dropArguments(mh, 0, Object.class);
                    }
                }
                case STATIC_RECEIVER -> {
                    if (!wantsContext) {
                        mh = MethodHandles.dropArguments(mh, 0, Object.class);
                    }
                }
                case FACTORY -> {
                    if (!wantsContext) {
                        mh = MethodHandles.dropArguments(mh, 0, Object.class);
                    }
                    mh = MethodHandles.dropArguments(mh, 1, Object.class);
                }
            }
            return mh.asType(MethodType.genericMethodType(arity + 2));
        } catch (IllegalAccessException e) {
            throw new IllegalArgumentException("cannot access " + member + ": " + e.getMessage(), e);
        }
    }

    /**
     * Runs the operation. {@code target} is what the Java code receives (the implementation
     * object); {@code answerForVoid} is what a method returning nothing answers (the receiver).
     * The arguments are converted in place: {@code args} must belong to this call.
     */
    Object invoke(CallContext context, Object target, Object[] args, Object answerForVoid) {
        Object[] a = args;
        for (int i = 0; i < converters.length; i++) {
            Converter c = converters[i];
            if (c != null) {
                a[i] = c.convert(a[i]);
            }
        }
        Object ctx = wantsContext ? context : null;
        Object result;
        try {
            result = switch (a.length) {
                case 0 -> (Object) handle.invokeExact(ctx, target);
                case 1 -> (Object) handle.invokeExact(ctx, target, a[0]);
                case 2 -> (Object) handle.invokeExact(ctx, target, a[0], a[1]);
                case 3 -> (Object) handle.invokeExact(ctx, target, a[0], a[1], a[2]);
                case 4 -> (Object) handle.invokeExact(ctx, target, a[0], a[1], a[2], a[3]);
                default -> handle.invokeWithArguments(prepend(ctx, target, a));
            };
        } catch (PonderError | ExitRequest e) {
            throw e;
        } catch (StackOverflowError e) {
            throw new UnitAbort("stack exhausted in '" + selector + "' of " + owner);
        } catch (Throwable e) {
            throw new PonderError("'" + selector + "' of " + owner + " failed: " + describe(e));
        }
        if (returnsVoid) {
            return answerForVoid;
        }
        try {
            return Converter.fromJava(result);
        } catch (PonderError e) {
            throw new PonderError("'" + selector + "' of " + owner + " failed: " + e.getMessage());
        }
    }

    /**
     * This operation with its receiver fixed to {@code target}: whatever receiver it is invoked on,
     * the Java method runs on {@code target} (a domain's extra operations, see
     * {@link ManagedClass#withOperationsOf}).
     */
    Operation boundTo(Object target) {
        MethodHandle bound = MethodHandles.dropArguments(MethodHandles.insertArguments(handle, 1, target), 1, Object.class);
        return new Operation(selector, arity, kind, bound, converters, returnsVoid, wantsContext, owner);
    }

    /** Whether the operation wants the call's context (and so a {@link CallContext} must be made). */
    boolean wantsContext() {
        return wantsContext;
    }

    private static String describe(Throwable e) {
        String m = e.getMessage();
        return m == null ? e.getClass().getSimpleName() : e.getClass().getSimpleName() + ": " + m;
    }

    private static List<Object> prepend(Object ctx, Object target, Object[] a) {
        Object[] all = new Object[a.length + 2];
        all[0] = ctx;
        all[1] = target;
        System.arraycopy(a, 0, all, 2, a.length);
        return Arrays.asList(all);
    }
}
