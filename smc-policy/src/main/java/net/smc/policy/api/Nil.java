package net.smc.policy.api;

/** PonderTalk's nil: answered by an untaken branch, a missing domain entry and the like. */
public final class Nil {
    public static final Nil NIL = new Nil();

    private Nil() {
    }

    @Override
    public String toString() {
        return "nil";
    }
}
