package net.smc.core.task;

/** A task with no annotated interface at all: its description is empty. */
public class Idler extends Task implements Runnable, Comparable<Idler> {
    @Override
    public void run() {
    }

    @Override
    public int compareTo(Idler other) {
        return 0;
    }
}
