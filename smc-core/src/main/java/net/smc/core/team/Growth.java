package net.smc.core.team;

/**
 * Grows a team that holds its minimal configuration towards the reasonably-optimal one (the
 * paper's Fig. 1 to Fig. 2), with the vehicles still free, never taking a role from anyone:
 * <ol>
 * <li>primary roles first, one holder per role per round, in planning order, until each reaches
 *     its optimal cardinality or no free vehicle can hold it;</li>
 * <li>then secondary roles, one step per role per round: a free vehicle of its own when the role is
 *     below optimal, else a free vehicle takes over the role from a vehicle that carried it beside
 *     its primary (the relay "is best placed in another UAV should there be one available");</li>
 * <li>last, secondary roles still below optimal ride on vehicles of their primary.</li>
 * </ol>
 * Rounds keep growth even: one role does not take every free vehicle before the next gets one.
 * Candidates are the least flexible capable vehicles first, lowest id among equals.
 */
final class Growth {
    private final Board board;
    private final RoleTable roles;
    private final Fleet fleet;
    /** Per role, its capable vehicles best first (built when first needed), and how far they are used. */
    private final int[][] candidates;
    private final int[] cursor;

    Growth(Board board) {
        this.board = board;
        this.roles = board.roles;
        this.fleet = board.fleet;
        candidates = new int[roles.size()][];
        cursor = new int[roles.size()];
    }

    void grow() {
        boolean progress = true;
        while (progress) {
            progress = false;
            for (int r : roles.order) {
                if (!roles.isSecondary(r) && board.count[r] < roles.opt[r]) {
                    int v = nextFree(r);
                    if (v >= 0) {
                        board.take(v, r);
                        progress = true;
                    }
                }
            }
        }
        progress = true;
        while (progress) {
            progress = false;
            for (int s : roles.order) {
                if (roles.isSecondary(s)) {
                    progress |= dedicate(s);
                }
            }
        }
        for (int s : roles.order) {
            if (roles.isSecondary(s)) {
                for (int v = 0; v < fleet.size() && board.count[s] < roles.opt[s]; v++) {
                    if (board.canCarry(v, s)) {
                        board.carry(v, s);
                    }
                }
            }
        }
    }

    /** Gives secondary role {@code s} one more vehicle of its own, if a free one can hold it. */
    private boolean dedicate(int s) {
        boolean below = board.count[s] < roles.opt[s];
        int carrier = below ? -1 : lastCarrier(s);
        if (!below && carrier < 0) {
            return false;
        }
        int v = nextFree(s);
        if (v < 0) {
            return false;
        }
        if (carrier >= 0) {
            board.uncarry(carrier, s);
        }
        board.take(v, s);
        return true;
    }

    /** The highest vehicle that carries {@code s} beside its primary, or -1. */
    private int lastCarrier(int s) {
        for (int v = fleet.size() - 1; v >= 0; v--) {
            if (board.holds(v, s) && board.anchor[v] != s) {
                return v;
            }
        }
        return -1;
    }

    /** The best free vehicle that can hold {@code r}, or -1. Vehicles never become free again while growing. */
    private int nextFree(int r) {
        if (candidates[r] == null) {
            // Sorted by (flexibility, vehicle), packed in one long each so that no boxing is needed.
            long[] keys = new long[fleet.size()];
            int n = 0;
            for (int v = 0; v < fleet.size(); v++) {
                if (fleet.capable(v, r)) {
                    keys[n++] = (long) fleet.flexibility[v] << 32 | v;
                }
            }
            java.util.Arrays.sort(keys, 0, n);
            candidates[r] = new int[n];
            for (int i = 0; i < n; i++) {
                candidates[r][i] = (int) keys[i];
            }
        }
        int[] list = candidates[r];
        while (cursor[r] < list.length && board.anchor[list[cursor[r]]] >= 0) {
            cursor[r]++;
        }
        return cursor[r] < list.length ? list[cursor[r]] : -1;
    }
}
