package net.smc.core.team;

/**
 * The planner's working state: which vehicle holds which roles. Every change has an exact inverse
 * so that the search can back out of a choice; counters kept on the way let it prune in O(roles).
 *
 * <p>A vehicle is free, or <em>anchored</em> at one role: a primary role (which may carry
 * secondary roles of that primary) or a secondary role of its own (a dedicated vehicle).
 */
final class Board {
    final RoleTable roles;
    final Fleet fleet;
    /** For each vehicle, the roles it holds. */
    final long[][] held;
    /** For each vehicle, the role it is anchored at, or -1 when free. */
    final int[] anchor;
    /** Holders of each role. */
    final int[] count;
    /** For each role, how many free vehicles may hold it. */
    final int[] freeCapable;
    /** For each secondary role, how many vehicles of its primary may hold it and do not yet. */
    final int[] carriable;
    int free;

    Board(RoleTable roles, Fleet fleet) {
        this.roles = roles;
        this.fleet = fleet;
        held = new long[fleet.size()][roles.words];
        anchor = new int[fleet.size()];
        java.util.Arrays.fill(anchor, -1);
        count = new int[roles.size()];
        freeCapable = new int[roles.size()];
        carriable = new int[roles.size()];
        free = fleet.size();
        for (int v = 0; v < fleet.size(); v++) {
            for (int r = BitArrays.next(fleet.capable[v], 0); r >= 0; r = BitArrays.next(fleet.capable[v], r + 1)) {
                freeCapable[r]++;
            }
        }
    }

    private Board(Board other) {
        roles = other.roles;
        fleet = other.fleet;
        held = new long[other.held.length][];
        for (int v = 0; v < held.length; v++) {
            held[v] = other.held[v].clone();
        }
        anchor = other.anchor.clone();
        count = other.count.clone();
        freeCapable = other.freeCapable.clone();
        carriable = other.carriable.clone();
        free = other.free;
    }

    Board copy() {
        return new Board(this);
    }

    boolean holds(int v, int r) {
        return BitArrays.get(held[v], r);
    }

    /** Anchors free vehicle {@code v} at role {@code r} (a primary role, or a secondary role on a vehicle of its own). */
    void take(int v, int r) {
        anchor[v] = r;
        BitArrays.set(held[v], r);
        count[r]++;
        free--;
        long[] capable = fleet.capable[v];
        for (int t = BitArrays.next(capable, 0); t >= 0; t = BitArrays.next(capable, t + 1)) {
            freeCapable[t]--;
        }
        if (!roles.isSecondary(r)) {
            for (int s : roles.secondariesOf[r]) {
                if (fleet.capable(v, s)) {
                    carriable[s]++;
                }
            }
        }
    }

    /** Undoes {@link #take}; the vehicle must carry nothing. */
    void untake(int v, int r) {
        if (!roles.isSecondary(r)) {
            for (int s : roles.secondariesOf[r]) {
                if (fleet.capable(v, s)) {
                    carriable[s]--;
                }
            }
        }
        long[] capable = fleet.capable[v];
        for (int t = BitArrays.next(capable, 0); t >= 0; t = BitArrays.next(capable, t + 1)) {
            freeCapable[t]++;
        }
        free++;
        count[r]--;
        BitArrays.clear(held[v], r);
        anchor[v] = -1;
    }

    /** Whether {@code v}, anchored at the primary of secondary role {@code s}, may carry {@code s} beside what it holds. */
    boolean canCarry(int v, int s) {
        if (anchor[v] != roles.primaryOf[s] || !fleet.capable(v, s) || holds(v, s)) {
            return false;
        }
        for (int t = BitArrays.next(held[v], 0); t >= 0; t = BitArrays.next(held[v], t + 1)) {
            if (!roles.share[s][t]) {
                return false;
            }
        }
        return true;
    }

    /** Lets {@code v} carry secondary role {@code s}; {@link #canCarry} must hold. */
    void carry(int v, int s) {
        BitArrays.set(held[v], s);
        count[s]++;
        carriable[s]--;
    }

    void uncarry(int v, int s) {
        carriable[s]++;
        count[s]--;
        BitArrays.clear(held[v], s);
    }

    /** Whether every role has at least its minimal number of holders. */
    boolean minimalMet() {
        for (int r = 0; r < roles.size(); r++) {
            if (count[r] < roles.min[r]) {
                return false;
            }
        }
        return true;
    }
}
