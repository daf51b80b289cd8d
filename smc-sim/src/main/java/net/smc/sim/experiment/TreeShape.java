package net.smc.sim.experiment;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

/**
 * How many roles (seats) a generated mission has at each level of its management tree, and how
 * they are grouped into role types. Level 0 is the commander; level 1 has one role type per
 * <i>branch</i>, each with one seat; the seats of every deeper level are shared out evenly over the
 * branches that reach the level above, one role type per branch and level ({@code b3l2}: branch 3,
 * level 2), whose seats the seats of the level above in the same branch manage in turn (seat
 * {@code j} by seat {@code j mod n}). So with fan-out 10 and 1,000 roles the levels hold 1, 10, 100
 * and 889 seats and every manager has about 10 children, in either scheme's tree of role types.
 *
 * @param roles  the number of roles (seats), the commander's included
 * @param depth  the number of levels, the commander's included (2 or more)
 * @param fanOut the most children of a seat in the distributed tree
 */
public record TreeShape(int roles, int depth, int fanOut) {
    /** The largest mission generated: seats are numbered in an int, and each needs a cell. */
    public static final int MAX_ROLES = 100_000;

    public TreeShape {
        if (depth < 2) {
            throw new IllegalArgumentException("tree depth " + depth + " is too small; it must be 2 or more (a commander and the roles it manages)");
        }
        if (roles < depth || roles > MAX_ROLES) {
            throw new IllegalArgumentException("number of roles " + roles + " cannot fill a tree of depth " + depth
                    + "; it must be from " + depth + " (one per level) to " + MAX_ROLES);
        }
        if (fanOut < 1) {
            throw new IllegalArgumentException("fan-out " + fanOut + " is not positive; it must be 1 or more");
        }
        if (capacity(depth, fanOut) < roles) {
            throw new IllegalArgumentException("a tree of depth " + depth + " and fan-out " + fanOut + " holds at most "
                    + capacity(depth, fanOut) + " roles; " + roles + " asked for (raise the fan-out or the depth)");
        }
    }

    /** The shape with the smallest fan-out that holds {@code roles} in {@code depth} levels. */
    public static TreeShape of(int roles, int depth) {
        if (depth < 2) {
            return new TreeShape(roles, depth, 1);   // throws with the reason
        }
        int f = 1;
        while (capacity(depth, f) < roles) {
            f++;
        }
        return new TreeShape(roles, depth, f);
    }

    /** Seats a full tree holds: 1 + f + f^2 + ... + f^(depth-1), capped far above {@link #MAX_ROLES}. */
    static long capacity(int depth, int fanOut) {
        long sum = 0;
        long level = 1;
        for (int k = 0; k < depth; k++) {
            sum += level;
            level = Math.min(level * fanOut, Integer.MAX_VALUE);
        }
        return sum;
    }

    /** Seats per level, the commander's (1) first: upper levels full, every level at least one seat. */
    public List<Integer> levelSizes() {
        List<Integer> sizes = new ArrayList<>();
        sizes.add(1);
        int used = 1;
        long full = 1;
        for (int k = 1; k < depth; k++) {
            full = Math.min(full * fanOut, Integer.MAX_VALUE);
            int size = (int) Math.min(full, roles - used - (depth - 1 - k));
            sizes.add(size);
            used += size;
        }
        return Collections.unmodifiableList(sizes);
    }

    /**
     * Seats per branch and level: {@code [branch][level]}, level 0 unused (the commander). Level 1
     * has one seat per branch; a deeper level's seats go evenly to the branches that have seats at
     * the level above, the first ones getting one more when they do not divide.
     */
    public int[][] seatsPerBranch() {
        List<Integer> sizes = levelSizes();
        int branches = sizes.get(1);
        int[][] seats = new int[branches][depth];
        for (int b = 0; b < branches; b++) {
            seats[b][1] = 1;
        }
        for (int k = 2; k < depth; k++) {
            List<Integer> eligible = new ArrayList<>();
            for (int b = 0; b < branches; b++) {
                if (seats[b][k - 1] > 0) {
                    eligible.add(b);
                }
            }
            int size = sizes.get(k);
            for (int i = 0; i < eligible.size(); i++) {
                seats[eligible.get(i)][k] = size / eligible.size() + (i < size % eligible.size() ? 1 : 0);
            }
        }
        return seats;
    }
}
