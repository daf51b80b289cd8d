package net.smc.policy.runtime;

import net.smc.policy.api.Handle;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import net.smc.policy.api.Diagnostic;
import net.smc.policy.api.PonderError;

/**
 * What other cells of the team send to this one's standard objects, run here under this cell's
 * authorisation policies, with the caller's subject (a peer of a receiving role, made by the
 * cell's owner) as the subject of every check:
 * <ul>
 * <li>an event an {@code EventForwarder} forwarded to {@code /team/<this cell>/<path>}: raised at
 *     that domain when the action {@value #FORWARDED_EVENT} on it is allowed (the cell's default
 *     decision applies when no policy does), or sent there as a one-argument message with the event
 *     as a hash (an ordinary send, checked as such);</li>
 * <li>PonderTalk text sent by a remote {@code PonderTalk}: evaluated only when a policy explicitly
 *     allows the action {@value #REMOTE_EVALUATION} on the receiving role's domain (denied by
 *     default, whatever the cell's default decision), then every send of the text is checked with
 *     the caller as its subject.</li>
 * </ul>
 * Every refusal or failure is a {@link PonderError} whose message is the answer to the sender.
 */
public final class TeamArrivals {
    /** The authorisation action of an event forwarded from another cell, on the domain it is raised at. */
    public static final String FORWARDED_EVENT = "forwardTo:";
    /** The authorisation action of PonderTalk from another cell, on the receiving role's domain. */
    public static final String REMOTE_EVALUATION = "evaluate:";

    private final CellRuntime runtime;

    public TeamArrivals(CellRuntime runtime) {
        this.runtime = runtime;
    }

    /**
     * Raises (or, with {@code selector}, sends) an event that arrived from another cell at the
     * object at {@code path} below root.
     *
     * @param event      the template's name under {@code root/event}
     * @param attributes the event's attributes by name (Java values: lists, maps, numbers, strings)
     * @throws PonderError when the path, the template or an attribute is missing, or it is denied
     */
    public void receiveEvent(Object subject, String path, String selector, String event, Map<String, Object> attributes) {
        Object target = path.isEmpty() ? runtime.root() : runtime.resolve("root/" + path);
        if (!(target instanceof ManagedObject at)) {
            throw new PonderError("'" + path + "' is a value, not a domain or managed object, so no event can be forwarded to it");
        }
        Object found = runtime.root().get("event") instanceof Domain events ? events.get(event) : null;
        if (!(found instanceof EventTemplate template)) {
            throw new PonderError("no event template root/event/" + event + " here for the forwarded event");
        }
        PHash hash = new PHash();
        Object[] values = new Object[template.attributeNames().size()];
        for (int i = 0; i < values.length; i++) {
            String name = template.attributeNames().get(i);
            if (!attributes.containsKey(name)) {
                throw new PonderError("forwarded event '" + event + "' lacks attribute '" + name + "' of root/event/" + event
                        + " (it has " + attributes.keySet() + ")");
            }
            values[i] = CellRuntime.fromJava(attributes.get(name));
            hash.put(name, values[i]);
        }
        if (selector != null) {
            runtime.sendAs(subject, at, selector, new Object[] {hash});
            return;
        }
        Execution ex = runtime.newExecution(subject);
        Authoriser auth = runtime.authoriser();
        if (auth != null && !auth.permits(ex, subject, at, FORWARDED_EVENT, new Object[] {hash}, false)) {
            throw new PonderError("Ponder2AuthorizationException: " + FORWARDED_EVENT + " (event '" + event + "' at root/" + path + ")");
        }
        try {
            runtime.deliverAt(ex, at, template, values);
        } finally {
            runtime.finish(ex);
        }
    }

    /**
     * Evaluates PonderTalk text from another cell, with {@code subject} as its source, if a policy
     * allows {@value #REMOTE_EVALUATION} of {@code subject} on {@code on}.
     *
     * @param on      the receiving role's domain (a handle the engine made)
     * @param source  the name the text runs under in diagnostics
     * @param printed whether to answer the value's printed form
     * @return the value of the text's last statement
     * @throws PonderError when it is denied, does not parse (the first syntax error), or fails
     */
    public Object evaluate(Object subject, Handle on, String source, String text, boolean printed) {
        Execution ex = runtime.newExecution(subject);
        Authoriser auth = runtime.authoriser();
        if (auth == null) {
            throw new PonderError("Ponder2AuthorizationException: " + REMOTE_EVALUATION
                    + " (this cell checks no authorisations, so it evaluates nothing for other cells)");
        }
        if (!auth.permits(ex, subject, (ManagedObject) on, REMOTE_EVALUATION, new Object[] {text}, true)) {
            throw new PonderError("Ponder2AuthorizationException: " + REMOTE_EVALUATION
                    + " (no authorisation policy allows it, and remote evaluation is denied by default)");
        }
        List<Diagnostic> syntax = new ArrayList<>();
        java.util.function.Consumer<Diagnostic> listener = syntax::add;
        runtime.listen(listener);
        try {
            Object value = runtime.evaluate(ex, source, text);
            return printed ? Values.print(value) : value;
        } catch (PonderError e) {
            boolean unparsed = e.getMessage() != null && e.getMessage().startsWith("cannot run '") && !syntax.isEmpty();
            throw new PonderError(unparsed ? syntax.get(0).toString() : e.getMessage());
        } catch (ExitRequest exit) {
            throw new PonderError("root exit is not done for another cell; nothing else of the text ran after it");
        } catch (StackOverflowError deep) {
            throw new PonderError("the text nests too deeply for this cell");
        } finally {
            runtime.unlisten(listener);
            runtime.finish(ex);
        }
    }
}
