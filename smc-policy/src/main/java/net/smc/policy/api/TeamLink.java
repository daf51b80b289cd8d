package net.smc.policy.api;

import java.util.Map;

/**
 * How the standard objects of a cell reach the other cells of its team ({@code EventForwarder
 * forwardTo: "/team/a1/..."}, {@code PonderTalk create: "/team/a1"}). The engine knows no network:
 * the owner of the cell (smc-core's team cell) gives it a link over its authenticated transport with
 * {@code PolicyEngine.teamLink(...)}. Every method returns at once with a call number; the answer,
 * or the error, comes back later as the event {@code remoteResult(call ok value error)} of the
 * sending cell. A cell without a team has {@link #NONE}.
 */
public interface TeamLink {

    /**
     * Sends an event to {@code to} (a domain or object of another cell), to be raised there
     * ({@code selector} null) or sent as the one-argument message {@code selector} with the
     * attributes as a hash.
     *
     * @param event      the name of the event's template under {@code root/event}, the same in every cell
     * @param attributes the event's attributes by name, in the template's order
     * @return the call number of the {@code remoteResult} that answers it
     * @throws PonderError when the link cannot send it at all
     */
    long forwardEvent(TeamAddress to, String selector, String event, Map<String, Object> attributes);

    /**
     * Sends PonderTalk text to cell {@code to} to be evaluated there; the answer is the value of its
     * last statement ({@code printed}: its printed form).
     *
     * @return the call number of the {@code remoteResult} that answers it
     */
    long evaluate(String to, String text, boolean printed);

    /** The link of a cell that is not in a team: every use is an error. */
    TeamLink NONE = new TeamLink() {
        @Override
        public long forwardEvent(TeamAddress to, String selector, String event, Map<String, Object> attributes) {
            throw new PonderError("this cell is not part of a team, so it cannot reach " + to);
        }

        @Override
        public long evaluate(String to, String text, boolean printed) {
            throw new PonderError("this cell is not part of a team, so it cannot reach " + TeamAddress.PREFIX + to);
        }
    };
}
