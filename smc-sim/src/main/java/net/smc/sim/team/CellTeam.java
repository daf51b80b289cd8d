package net.smc.sim.team;

import java.util.Collection;
import java.util.function.BooleanSupplier;
import java.util.function.Supplier;

import net.smc.core.cell.Cell;
import net.smc.core.transport.Address;
import net.smc.core.transport.sim.SimulationScheduler;

/**
 * A team of vehicles' cells in a world, as a scenario and the world's hardware see it: the
 * simulation on one virtual clock ({@link TeamSimulation}) or cells on real UDP with the world
 * stepped in real time ({@link LiveTeam}). Cells, the world and its scheduler are touched only
 * from inside {@link #exclusive}, or from the callbacks the team makes (listeners, policy output,
 * world steps), which already hold it.
 */
public interface CellTeam extends AutoCloseable {
    /** Starts the world and every vehicle's cell. */
    void start();

    /** The mission time, ms. */
    long nowMillis();

    /**
     * Runs (or waits, on a real clock) until {@code condition} holds, at most {@code maxMillis} of
     * mission time; the condition is checked inside {@link #exclusive}.
     *
     * @return whether it came to hold
     */
    boolean runUntil(BooleanSupplier condition, long maxMillis);

    /** The live cell of a vehicle, or null while it is not running. */
    Cell cell(String vehicle);

    Collection<SimVehicle> vehicles();

    SimVehicle vehicle(String id);

    boolean isLive(String vehicle);

    /** Where {@code vehicle} is attached to the network. */
    Address address(String vehicle);

    /** The world's side of the team, or null when it has no world. */
    WorldTeam world();

    /** The scheduler the world steps on. */
    SimulationScheduler scheduler();

    /**
     * Runs {@code action} while no cell and no world step runs; what it returns is passed on. In
     * simulation everything runs on the caller's thread, so this only calls it.
     */
    default <T> T exclusive(Supplier<T> action) {
        return action.get();
    }

    /** Stops what runs on threads of its own (nothing in simulation). */
    @Override
    default void close() {
    }
}
