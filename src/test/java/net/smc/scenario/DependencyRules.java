package net.smc.scenario;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

/**
 * The project's architecture rules, checked on Java source text (no compiler, no class files).
 * A package depends on another when one of its files imports a type of it or names it fully
 * qualified in code (comments and string literals do not count); same-package references need no
 * import and make no edge. The rules:
 *
 * <ol>
 *   <li>no cycle among the packages of the main sources;</li>
 *   <li>modules depend one way, on earlier modules of {@link #modules} only
 *       ({@code smc-policy <- smc-core <- smc-sim <- smc-demo});</li>
 *   <li>an inside package of a module (the engine's {@code net.smc.policy.runtime}) is imported from
 *       its own module only;</li>
 *   <li>no two top-level main types share a simple name.</li>
 * </ol>
 *
 * <p>{@link #violations} lists every broken rule as one line; {@link ArchitectureTest} runs it on the
 * real sources and {@code DependencyRulesTest} shows each rule failing on small synthetic inputs.
 *
 * @param modules         the modules in dependency order: each may use only those before it
 * @param insidePackages  inside packages, each with the module that owns it
 */
record DependencyRules(List<String> modules, Map<String, String> insidePackages) {

    /** One main source file: the module it belongs to, its path (for messages) and its text. */
    record Source(String module, String path, String text) {
    }

    private static final Pattern PACKAGE = Pattern.compile("^\\s*package\\s+([\\w.]+)\\s*;", Pattern.MULTILINE);
    private static final Pattern IMPORT = Pattern.compile("^\\s*import\\s+(?:static\\s+)?([\\w.]+)(?:\\.\\*)?\\s*;",
            Pattern.MULTILINE);
    private static final Pattern QUALIFIED = Pattern.compile("(?<![\\w.])((?:[a-z_]\\w*\\.)+)[A-Z]");
    private static final Pattern TOP_TYPE = Pattern.compile(
            "^(?:public\\s+|final\\s+|abstract\\s+|sealed\\s+|non-sealed\\s+|strictfp\\s+)*"
                    + "(?:class|interface|enum|record|@interface)\\s+(\\w+)", Pattern.MULTILINE);

    /** Reads every {@code .java} file under {@code MODULE/src/main/java} of each module. */
    static List<Source> readMainSources(Path projectDir, List<String> modules) {
        List<Source> sources = new ArrayList<>();
        for (String module : modules) {
            Path root = projectDir.resolve(module).resolve("src/main/java");
            try (Stream<Path> files = Files.walk(root)) {
                for (Path file : files.filter(f -> f.toString().endsWith(".java")).sorted().toList()) {
                    sources.add(new Source(module, projectDir.relativize(file).toString(), Files.readString(file)));
                }
            } catch (IOException e) {
                throw new UncheckedIOException("cannot read the sources of " + module + " in " + root, e);
            }
        }
        return sources;
    }

    /** Every broken rule, one line each, sorted; empty when the sources keep all of them. */
    List<String> violations(List<Source> sources) {
        Map<String, String> moduleOf = new HashMap<>();
        Map<String, Set<String>> edges = new TreeMap<>();
        Map<String, String> edgeWitness = new HashMap<>();
        Map<String, List<String>> typesByName = new TreeMap<>();
        for (Source s : sources) {
            String pkg = packageOf(s);
            moduleOf.putIfAbsent(pkg, s.module());
            edges.computeIfAbsent(pkg, p -> new TreeSet<>());
            for (String type : topLevelTypes(s)) {
                typesByName.computeIfAbsent(type, t -> new ArrayList<>()).add(pkg + "." + type);
            }
        }
        TreeSet<String> violations = new TreeSet<>();
        for (Source s : sources) {
            String from = packageOf(s);
            for (String to : referencedPackages(s.text())) {
                if (to.equals(from) || !moduleOf.containsKey(to)) {
                    continue;
                }
                edges.get(from).add(to);
                edgeWitness.putIfAbsent(from + " -> " + to, s.path());
                String fromModule = s.module();
                String toModule = moduleOf.get(to);
                if (modules.indexOf(toModule) > modules.indexOf(fromModule)) {
                    violations.add("module direction: " + s.path() + " (" + fromModule + ") uses " + to + " ("
                            + toModule + "); " + fromModule + " may use only " + modules.subList(0, modules.indexOf(fromModule)));
                }
                String owner = insidePackages.get(to);
                if (owner != null && !owner.equals(fromModule)) {
                    violations.add("inside package: " + s.path() + " (" + fromModule + ") uses " + to
                            + ", the inside of " + owner + "; use its public packages");
                }
            }
        }
        for (List<String> cycle : cycles(edges)) {
            List<String> steps = new ArrayList<>();
            for (int i = 0; i < cycle.size(); i++) {
                String edge = cycle.get(i) + " -> " + cycle.get((i + 1) % cycle.size());
                steps.add(edge + " (" + edgeWitness.get(edge) + ")");
            }
            violations.add("package cycle: " + String.join(", ", steps));
        }
        typesByName.forEach((name, types) -> {
            if (types.size() > 1) {
                violations.add("simple name: " + types.size() + " main types are called " + name + ": " + types);
            }
        });
        return List.copyOf(violations);
    }

    private static String packageOf(Source s) {
        Matcher m = PACKAGE.matcher(s.text());
        if (!m.find()) {
            throw new IllegalArgumentException(s.path() + " has no package declaration");
        }
        return m.group(1);
    }

    private static List<String> topLevelTypes(Source s) {
        if (s.path().endsWith("package-info.java")) {
            return List.of();
        }
        List<String> names = new ArrayList<>();
        Matcher m = TOP_TYPE.matcher(stripCommentsAndLiterals(s.text()));
        while (m.find()) {
            names.add(m.group(1));
        }
        return names;
    }

    /** The packages a file names in its imports or in fully qualified references in code. */
    static Set<String> referencedPackages(String text) {
        String code = stripCommentsAndLiterals(text);
        Set<String> packages = new TreeSet<>();
        Matcher imports = IMPORT.matcher(code);
        while (imports.find()) {
            packages.add(packagePart(imports.group(1)));
        }
        String body = IMPORT.matcher(PACKAGE.matcher(code).replaceAll("")).replaceAll("");
        Matcher qualified = QUALIFIED.matcher(body);
        while (qualified.find()) {
            String prefix = qualified.group(1);
            packages.add(prefix.substring(0, prefix.length() - 1));
        }
        return packages;
    }

    /** {@code a.b.C.D} and {@code a.b.C.member} name package {@code a.b}; {@code a.b} (a wildcard) is itself. */
    private static String packagePart(String name) {
        String[] parts = name.split("\\.");
        StringBuilder pkg = new StringBuilder();
        for (String part : parts) {
            if (Character.isUpperCase(part.charAt(0))) {
                break;
            }
            pkg.append(pkg.length() == 0 ? "" : ".").append(part);
        }
        return pkg.toString();
    }

    /** The text with comments, string, text-block and char literals blanked (line breaks kept). */
    static String stripCommentsAndLiterals(String text) {
        StringBuilder out = new StringBuilder(text.length());
        int i = 0;
        int n = text.length();
        while (i < n) {
            char c = text.charAt(i);
            if (c == '/' && i + 1 < n && text.charAt(i + 1) == '/') {
                while (i < n && text.charAt(i) != '\n') {
                    i++;
                }
            } else if (c == '/' && i + 1 < n && text.charAt(i + 1) == '*') {
                int end = text.indexOf("*/", i + 2);
                end = end < 0 ? n : end + 2;
                keepLineBreaks(out, text, i, end);
                i = end;
            } else if (text.startsWith("\"\"\"", i)) {
                int end = text.indexOf("\"\"\"", i + 3);
                end = end < 0 ? n : end + 3;
                keepLineBreaks(out, text, i, end);
                out.append("\"\"");
                i = end;
            } else if (c == '"' || c == '\'') {
                int j = i + 1;
                while (j < n && text.charAt(j) != c && text.charAt(j) != '\n') {
                    j += text.charAt(j) == '\\' ? 2 : 1;
                }
                out.append(c).append(c);
                i = Math.min(j + 1, n);
            } else {
                out.append(c);
                i++;
            }
        }
        return out.toString();
    }

    private static void keepLineBreaks(StringBuilder out, String text, int from, int to) {
        for (int k = from; k < to; k++) {
            if (text.charAt(k) == '\n') {
                out.append('\n');
            }
        }
    }

    /** The package cycles: each strongly connected component of two or more packages, as one cycle through it. */
    private static List<List<String>> cycles(Map<String, Set<String>> edges) {
        List<List<String>> result = new ArrayList<>();
        for (Set<String> component : stronglyConnected(edges)) {
            if (component.size() > 1) {
                result.add(cycleThrough(component, edges));
            }
        }
        return result;
    }

    /** Tarjan's algorithm, iterative over the sorted graph so that results are stable. */
    private static List<Set<String>> stronglyConnected(Map<String, Set<String>> edges) {
        Map<String, Integer> index = new HashMap<>();
        Map<String, Integer> low = new HashMap<>();
        Deque<String> stack = new ArrayDeque<>();
        Set<String> onStack = new TreeSet<>();
        List<Set<String>> components = new ArrayList<>();
        int[] counter = {0};
        for (String start : edges.keySet()) {
            if (!index.containsKey(start)) {
                strongConnect(start, edges, index, low, stack, onStack, components, counter);
            }
        }
        return components;
    }

    private static void strongConnect(String v, Map<String, Set<String>> edges, Map<String, Integer> index,
                                      Map<String, Integer> low, Deque<String> stack, Set<String> onStack,
                                      List<Set<String>> components, int[] counter) {
        index.put(v, counter[0]);
        low.put(v, counter[0]);
        counter[0]++;
        stack.push(v);
        onStack.add(v);
        for (String w : edges.getOrDefault(v, Set.of())) {
            if (!index.containsKey(w)) {
                strongConnect(w, edges, index, low, stack, onStack, components, counter);
                low.put(v, Math.min(low.get(v), low.get(w)));
            } else if (onStack.contains(w)) {
                low.put(v, Math.min(low.get(v), index.get(w)));
            }
        }
        if (low.get(v).equals(index.get(v))) {
            Set<String> component = new TreeSet<>();
            String w;
            do {
                w = stack.pop();
                onStack.remove(w);
                component.add(w);
            } while (!w.equals(v));
            components.add(component);
        }
    }

    /** A shortest cycle from the component's first package back to itself, staying inside the component. */
    private static List<String> cycleThrough(Set<String> component, Map<String, Set<String>> edges) {
        String start = component.iterator().next();
        Map<String, String> parent = new HashMap<>();
        Deque<String> queue = new ArrayDeque<>(List.of(start));
        while (!queue.isEmpty()) {
            String v = queue.removeFirst();
            for (String w : edges.getOrDefault(v, Set.of())) {
                if (!component.contains(w)) {
                    continue;
                }
                if (w.equals(start)) {
                    List<String> path = new ArrayList<>();
                    for (String p = v; p != null; p = parent.get(p)) {
                        path.add(0, p);
                    }
                    return path;
                }
                if (!parent.containsKey(w)) {
                    parent.put(w, v);
                    queue.addLast(w);
                }
            }
        }
        throw new IllegalStateException("no cycle through " + component);
    }
}
