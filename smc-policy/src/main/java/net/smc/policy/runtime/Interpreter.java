package net.smc.policy.runtime;

import net.smc.policy.api.Nil;
import net.smc.policy.api.PonderError;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import net.smc.policy.lang.Node;
import net.smc.policy.lang.SourcePos;

/**
 * Runs PonderTalk: compiles each top-level statement's syntax tree into a tree of executable nodes
 * just before it runs, and drops it after (blocks keep the code they were made from). Sends go through per-site caches of the receiver's dispatch table; every send
 * counts against the run's step limit, and managed-object targets pass authorisation when it is on.
 */
public final class Interpreter {
    private final CellRuntime runtime;

    Interpreter(CellRuntime runtime) {
        this.runtime = runtime;
    }

    CellRuntime runtime() {
        return runtime;
    }

    /** Executable code: one node of the compiled tree. */
    abstract static class Code {
        abstract Object exec(VariableFrame f);
    }

    private Code[] compileAll(List<Node> nodes) {
        Code[] out = new Code[nodes.size()];
        for (int i = 0; i < out.length; i++) {
            out[i] = compile(nodes.get(i));
        }
        return out;
    }

    private Code compile(Node node) {
        if (node instanceof Node.Literal lit) {
            return new Const(lit.value());
        }
        if (node instanceof Node.Name name) {
            return new NameCode(name);
        }
        if (node instanceof Node.Assign assign) {
            return new AssignCode(assign.name().intern(), compile(assign.value()));
        }
        if (node instanceof Node.ArrayLiteral array) {
            return new ArrayCode(compileAll(array.elements()));
        }
        if (node instanceof Node.BlockLiteral block) {
            String[] params = block.params().stream().map(String::intern).toArray(String[]::new);
            Set<String> free = new LinkedHashSet<>();
            for (Node statement : block.statements()) {
                readNames(statement, free);
            }
            free.removeAll(List.of(params));
            String[] freeNames = free.stream().map(String::intern).toArray(String[]::new);
            return new BlockCode(params, freeNames, compileAll(block.statements()), block.pos());
        }
        if (node instanceof Node.Send send) {
            return new SendCode(this, compile(send.receiver()), send.message());
        }
        Node.Cascade cascade = (Node.Cascade) node;
        SendCode[][] chains = new SendCode[cascade.chains().size()][];
        for (int i = 0; i < chains.length; i++) {
            List<Node.Message> chain = cascade.chains().get(i);
            chains[i] = new SendCode[chain.size()];
            for (int j = 0; j < chain.size(); j++) {
                chains[i][j] = new SendCode(this, null, chain.get(j));
            }
        }
        return new CascadeCode(compile(cascade.receiver()), chains);
    }

    /** Collects the first segment of every relative name the node reads, nested blocks included. */
    private static void readNames(Node node, Set<String> out) {
        if (node instanceof Node.Name name) {
            if (!name.absolute()) {
                out.add(name.segments().get(0));
            }
        } else if (node instanceof Node.Assign assign) {
            readNames(assign.value(), out);
        } else if (node instanceof Node.ArrayLiteral array) {
            array.elements().forEach(e -> readNames(e, out));
        } else if (node instanceof Node.BlockLiteral block) {
            block.statements().forEach(s -> readNames(s, out));
        } else if (node instanceof Node.Send send) {
            readNames(send.receiver(), out);
            send.message().args().forEach(a -> readNames(a, out));
        } else if (node instanceof Node.Cascade cascade) {
            readNames(cascade.receiver(), out);
            cascade.chains().forEach(chain -> chain.forEach(m -> m.args().forEach(a -> readNames(a, out))));
        }
    }

    /** Compiles and runs one top-level statement of a unit in the unit's frame; answers its value. */
    Object run(Node statement, VariableFrame frame) {
        frame.ex.checkStop();
        return compile(statement).exec(frame);
    }

    /** Calls a block: binds its parameters to {@code args} (extra arguments are ignored). */
    public Object call(Execution ex, Block block, Object... args) {
        return call(ex, block, args, NO_NAMES, null);
    }

    private static final String[] NO_NAMES = new String[0];

    /** Calls a block with extra variables bound in its call frame (as {@code p_subject} in conditions). */
    Object call(Execution ex, Block block, Object[] args, String[] extraNames, Object[] extraValues) {
        if (block.guarded != null) {
            try {
                return call(ex, block.guarded, args, extraNames, extraValues);
            } catch (UnitAbort abort) {
                throw abort;
            } catch (PonderError error) {
                return call(ex, block.handler, new ErrorValue(error));
            }
        }
        BlockCode code = block.code;
        ex.step();
        if (args.length < code.params.length) {
            throw new PonderError("Not enough arguments for block. " + args.length + " given, "
                    + code.params.length + " expected.");
        }
        ex.enterCall();
        try {
            VariableFrame frame = new VariableFrame(ex, code.free, block.captured, code.params, args, block.scope);
            for (int i = 0; i < extraNames.length; i++) {
                frame.set(extraNames[i], extraValues[i]);
            }
            Object value = Nil.NIL;
            for (Code statement : code.body) {
                value = statement.exec(frame);
            }
            return value;
        } finally {
            ex.leaveCall();
        }
    }

    /** Sends a message from Java, as a statement would. */
    Object send(Execution ex, Object receiver, String selector, Object[] arguments, SourcePos pos) {
        Object[] args = arguments.clone();
        ManagedClass type = ManagedClass.typeOf(receiver);
        Operation op = type.lookup(selector);
        if (op == null) {
            throw type.unknown(selector).at(pos);
        }
        try {
            return dispatch(ex, op, receiver, args, pos);
        } catch (PonderError e) {
            throw e.at(pos);
        }
    }

    /** Invokes an operation on a receiver, with authorisation when it applies. */
    Object dispatch(Execution ex, Operation op, Object receiver, Object[] args, SourcePos pos) {
        ex.step();
        Object target = receiver;
        if (receiver instanceof ManagedObject mo) {
            if (op.kind == Operation.Kind.INSTANCE) {
                target = mo.impl();
            }
            Authoriser auth = runtime.authoriser();
            if (auth != null && ex.source != runtime.root()) {
                return auth.invoke(this, ex, op, mo, target, args, pos);
            }
        }
        CallContext ctx = op.wantsContext() ? new CallContext(this, ex, receiver, pos) : null;
        return op.invoke(ctx, target, args, receiver);
    }

    /** Invokes without authorisation (the authoriser calls this once it has allowed the request). */
    Object invokeUnchecked(Execution ex, Operation op, Object receiver, Object target, Object[] args, SourcePos pos) {
        CallContext ctx = op.wantsContext() ? new CallContext(this, ex, receiver, pos) : null;
        return op.invoke(ctx, target, args, receiver);
    }

    private static final class Const extends Code {
        private final Object value;

        Const(Object value) {
            this.value = value;
        }

        @Override
        Object exec(VariableFrame f) {
            return value;
        }
    }

    private static final class NameCode extends Code {
        private final String first;
        private final String[] rest;
        private final String[] fromRoot;
        private final boolean absolute;
        private final String text;
        private final SourcePos pos;

        NameCode(Node.Name name) {
            List<String> segments = name.segments();
            this.first = segments.get(0).intern();
            this.rest = segments.subList(1, segments.size()).toArray(String[]::new);
            this.absolute = name.absolute();
            this.fromRoot = !absolute && first.equals("root") ? rest : segments.toArray(String[]::new);
            this.text = name.text();
            this.pos = name.pos();
        }

        @Override
        Object exec(VariableFrame f) {
            if (!absolute) {
                Object v = f.lookup(first);
                if (v == null && first == VariableFrame.VARIABLES) {
                    v = f.variables();
                }
                if (v != null) {
                    return rest.length == 0 ? v : walk(v, rest);
                }
            }
            return walk(f.ex.runtime.root(), fromRoot);
        }

        private Object walk(Object start, String[] segments) {
            Object at = start;
            for (String segment : segments) {
                Object next = at instanceof Domain d ? d.get(segment) : null;
                if (next == null) {
                    throw new PonderError("path not found '" + text + "'", pos);
                }
                at = next;
            }
            return at;
        }
    }

    private static final class AssignCode extends Code {
        private final String name;
        private final Code value;

        AssignCode(String name, Code value) {
            this.name = name;
            this.value = value;
        }

        @Override
        Object exec(VariableFrame f) {
            Object v = value.exec(f);
            f.set(name, v);
            return v;
        }
    }

    private static final class ArrayCode extends Code {
        private final Code[] elements;

        ArrayCode(Code[] elements) {
            this.elements = elements;
        }

        @Override
        Object exec(VariableFrame f) {
            PArray array = new PArray();
            for (Code element : elements) {
                array.add(element.exec(f));
            }
            return array;
        }
    }

    /** A block literal; executing it makes a {@link Block} that captures the frame's bindings. */
    static final class BlockCode extends Code {
        final String[] params;
        /** The names the block's code reads that are not its parameters: what it captures. */
        final String[] free;
        final Code[] body;
        final SourcePos pos;
        /** Whether the code reads {@code Variables}, so a block must capture every visible variable. */
        private final boolean readsVariables;

        BlockCode(String[] params, String[] free, Code[] body, SourcePos pos) {
            this.params = params;
            this.free = free;
            this.readsVariables = List.of(free).contains(VariableFrame.VARIABLES);
            this.body = body;
            this.pos = pos;
        }

        @Override
        Object exec(VariableFrame f) {
            return new Block(this, f.capture(free), readsVariables ? f.snapshot() : Map.of());
        }
    }

    /** One message send, with a cache of the last receiver class and its operation. */
    private static final class SendCode extends Code {
        private final Interpreter interpreter;
        private final Code receiver;
        private final String selector;
        private final Code[] args;
        private final SourcePos pos;
        private ManagedClass cachedType;
        private Operation cachedOp;

        SendCode(Interpreter interpreter, Code receiver, Node.Message message) {
            this.interpreter = interpreter;
            this.receiver = receiver;
            this.selector = message.selector();
            this.args = interpreter.compileAll(message.args());
            this.pos = message.pos();
        }

        @Override
        Object exec(VariableFrame f) {
            return sendTo(f, receiver.exec(f));
        }

        Object sendTo(VariableFrame f, Object target) {
            Object[] values = new Object[args.length];
            for (int i = 0; i < values.length; i++) {
                values[i] = args[i].exec(f);
            }
            ManagedClass type = ManagedClass.typeOf(target);
            Operation op;
            if (type == cachedType) {
                op = cachedOp;
            } else {
                op = type.lookup(selector);
                if (op == null) {
                    throw type.unknown(selector).at(pos);
                }
                cachedType = type;
                cachedOp = op;
            }
            try {
                return interpreter.dispatch(f.ex, op, target, values, pos);
            } catch (PonderError e) {
                throw e.at(pos);
            }
        }
    }

    private static final class CascadeCode extends Code {
        private final Code receiver;
        private final SendCode[][] chains;

        CascadeCode(Code receiver, SendCode[][] chains) {
            this.receiver = receiver;
            this.chains = chains;
        }

        @Override
        Object exec(VariableFrame f) {
            Object target = receiver.exec(f);
            Object value = target;
            for (SendCode[] chain : chains) {
                value = target;
                for (SendCode send : chain) {
                    value = send.sendTo(f, value);
                }
            }
            return value;
        }
    }
}
