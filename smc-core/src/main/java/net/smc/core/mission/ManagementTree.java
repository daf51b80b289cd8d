package net.smc.core.mission;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collections;
import java.util.Deque;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

/**
 * Who manages whom (the paper's Fig. 5): a tree rooted at the commander. A vehicle holding a role
 * runs discovery for the roles below it and watches their heartbeats, which is why the relation
 * must be a tree: a role with two managers would be assigned twice, and a cycle would never be
 * reached from the commander.
 *
 * @param root     the commander
 * @param children each role's managed roles in the class file's order; every role is a key
 */
public record ManagementTree(String root, Map<String, List<String>> children) {

    public ManagementTree {
        Map<String, List<String>> copy = new LinkedHashMap<>();
        children.forEach((role, managed) -> copy.put(role, List.copyOf(managed)));
        children = Collections.unmodifiableMap(copy);
    }

    /**
     * The tree the roles' {@code manages} lists form.
     *
     * @throws IllegalArgumentException naming the role when a managed role is unknown, a role has
     *                                  two managers, the commander is managed or missing, or a role
     *                                  cannot be reached from the commander
     */
    static ManagementTree of(List<MissionRole> roles) {
        Map<String, List<String>> children = new LinkedHashMap<>();
        roles.forEach(r -> children.put(r.name(), r.manages()));
        if (!children.containsKey(Mission.COMMANDER)) {
            throw new IllegalArgumentException("no role 'commander'; the management tree is rooted at the commander");
        }
        Map<String, String> parent = new LinkedHashMap<>();
        for (MissionRole role : roles) {
            for (String managed : role.manages()) {
                if (!children.containsKey(managed)) {
                    throw new IllegalArgumentException("role '" + role.name() + "' manages unknown role '" + managed + "'");
                }
                if (managed.equals(Mission.COMMANDER)) {
                    throw new IllegalArgumentException("role '" + role.name() + "' manages the commander; the commander is the root");
                }
                String before = parent.putIfAbsent(managed, role.name());
                if (before != null) {
                    throw new IllegalArgumentException("role '" + managed + "' is managed by both '" + before + "' and '"
                            + role.name() + "'; each role has one manager");
                }
            }
        }
        ManagementTree tree = new ManagementTree(Mission.COMMANDER, children);
        Set<String> reached = new java.util.HashSet<>(tree.breadthFirst());
        for (String role : children.keySet()) {
            if (!reached.contains(role)) {
                throw new IllegalArgumentException("role '" + role + "' cannot be reached from the commander; "
                        + "the management relation must be a tree rooted at the commander");
            }
        }
        return tree;
    }

    /** The role that manages {@code role}; empty for the commander. */
    public Optional<String> parentOf(String role) {
        for (Map.Entry<String, List<String>> entry : children.entrySet()) {
            if (entry.getValue().contains(role)) {
                return Optional.of(entry.getKey());
            }
        }
        return Optional.empty();
    }

    /** The roles {@code role} manages (empty for an unknown role). */
    public List<String> childrenOf(String role) {
        return children.getOrDefault(role, List.of());
    }

    /** The roles level by level from the commander, siblings in the class file's order. */
    public List<String> breadthFirst() {
        Set<String> order = new LinkedHashSet<>();
        Deque<String> queue = new ArrayDeque<>(List.of(root));
        while (!queue.isEmpty() && order.size() <= children.size()) {
            String role = queue.removeFirst();
            if (order.add(role)) {
                queue.addAll(childrenOf(role));
            }
        }
        return List.copyOf(order);
    }

    /**
     * The roles in depth-first pre-order (the order a listing indents them). Walked with a stack of
     * its own, not by recursion: a chain of thousands of managers is a valid tree.
     */
    public List<String> depthFirst() {
        Set<String> order = new LinkedHashSet<>();
        Deque<String> stack = new ArrayDeque<>(List.of(root));
        while (!stack.isEmpty()) {
            String role = stack.pop();
            if (order.add(role)) {
                List<String> below = childrenOf(role);
                for (int i = below.size() - 1; i >= 0; i--) {
                    stack.push(below.get(i));   // the first child on top: visited first
                }
            }
        }
        return List.copyOf(order);
    }

    /** Every role reached from the commander with how many managers are above it, in one walk. */
    public Map<String, Integer> depths() {
        Map<String, Integer> depths = new LinkedHashMap<>();
        Deque<String> queue = new ArrayDeque<>(List.of(root));
        depths.put(root, 0);
        while (!queue.isEmpty()) {
            String role = queue.removeFirst();
            for (String child : childrenOf(role)) {
                if (depths.putIfAbsent(child, depths.get(role) + 1) == null) {
                    queue.addLast(child);
                }
            }
        }
        return depths;
    }

    /** How many managers are above {@code role}: 0 for the commander. */
    public int depthOf(String role) {
        int depth = 0;
        for (Optional<String> up = parentOf(role); up.isPresent(); up = parentOf(up.get())) {
            depth++;
        }
        return depth;
    }
}
