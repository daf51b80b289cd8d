package net.smc.core.task;

/**
 * The example task: implements {@link ExplorerI}, and {@link Runnable}, an interface without
 * {@code @TaskInterface} that must contribute nothing to its description.
 */
public class Explorer extends Task implements ExplorerI, Runnable {
    double x;
    double y;
    String area = "";
    int runs;

    @Override
    public void moveTo(double toX, double toY) {
        x = toX;
        y = toY;
    }

    @Override
    public void explore(String name) {
        area = name;
        arrived(name);
    }

    @Override
    public String position() {
        return x + "," + y;
    }

    /** Raises the event into the task's cell: the event method is how the task raises it. */
    @Override
    public void obstacle(double atX, double atY) {
        raise("obstacle", atX, atY);
    }

    @Override
    public void arrived(String name) {
        raise("arrived", name);
    }

    @Override
    public void run() {
        runs++;
    }

    /** What the simulated sensor calls; the task reacts by raising its event. */
    void sense(double atX, double atY) {
        obstacle(atX, atY);
    }

    /** Misuse, for the tests: raises an event the task does not declare. */
    boolean raiseUndeclared() {
        return raise("meteor", 1);
    }

    /** Misuse, for the tests: raises a declared event with too few values. */
    boolean raiseTooFew() {
        return raise("obstacle", 1.0);
    }
}
