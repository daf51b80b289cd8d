package net.smc.core.role;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;
import net.smc.policy.PolicyEngine;
import net.smc.policy.api.Handle;

/**
 * Hears of every obligation and authorisation policy a cell creates while a role loads, however a
 * file made it (a factory, {@code root load:}), so that the Role-Manager knows every policy a file
 * created, even one the file activated and never stored.
 */
final class PolicyFactoryTap {
    private PolicyFactoryTap() {
    }

    /** A listening tap; {@link #close()} stops listening. */
    static final class Installed implements AutoCloseable {
        private final PolicyEngine cell;
        private final List<Handle> created = new ArrayList<>();
        private final Consumer<Handle> listener = created::add;
        private boolean open = true;

        private Installed(PolicyEngine cell) {
            this.cell = cell;
            cell.listenCreations(listener);
        }

        /** Policies created since the last call, in order. */
        List<Handle> drain() {
            List<Handle> out = List.copyOf(created);
            created.clear();
            return out;
        }

        /** Stops listening; closing twice is harmless. */
        @Override
        public void close() {
            if (open) {
                open = false;
                cell.unlistenCreations(listener);
            }
        }
    }

    static Installed install(PolicyEngine cell) {
        return new Installed(cell);
    }
}
