package net.smc.core.mission;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import net.smc.core.mission.ClassSpec.ParamDecl;
import net.smc.core.mission.ClassSpec.Ref;
import net.smc.core.mission.ClassSpec.RoleDecl;
import net.smc.core.mission.InstanceSpec.RoleEntry;
import net.smc.core.xml.XmlElement;
import net.smc.core.xml.XmlLimits;
import net.smc.core.xml.XmlReader;
import net.smc.core.xml.XmlRefusal;
import net.smc.policy.api.PolicyRepository;

/**
 * Start here: loads a mission instance file, the mission class file it names, checks both and
 * resolves every policy URI in a policy repository, giving an immutable {@link Mission}. This is
 * the first step of a mission: the acting commander loads what the command base sent.
 *
 * <pre>{@code
 * MissionLoader loader = new MissionLoader(new PolicyRepository(Path.of("policies")));
 * try {
 *     Mission mission = loader.load(Path.of("missions/reconnaissance.instance.xml"));
 *     TeamConfiguration team = TeamPlanner.plan(mission, vehicles);
 * } catch (MissionException e) {
 *     e.errors().forEach(err -> log.error("{}", err));   // FILE:LINE:COL: <element>: message
 * }
 * }</pre>
 *
 * <p>The instance names its class with {@code <missionClass href="reconnaissance.class.xml">},
 * relative to the instance file. Every error of both files is reported, not only the first; the
 * formats and rules are in {@code missions/README.md}. A loader keeps no state between loads
 * (its Stax factory is configured once and only creates readers), so threads may share one.
 */
public final class MissionLoader {
    /** The largest mission file read, in bytes; a larger one is refused unread. */
    public static final long MAX_FILE_BYTES = 1024 * 1024;

    private final PolicyRepository repository;
    private final List<Path> allowedDirs;
    /** The text of an element, or an attribute value, of a mission file has at most 4096 characters. */
    private static final XmlLimits LIMITS = new XmlLimits(MAX_FILE_BYTES, 4096, 4096);

    private final XmlReader xml = new XmlReader("mission file", "missions/*.xsd", LIMITS);

    /**
     * A loader that resolves policy URIs in {@code repository}; a class {@code href} must name a
     * file in the instance's folder or below it.
     */
    public MissionLoader(PolicyRepository repository) {
        this(repository, List.of());
    }

    /**
     * A loader that resolves policy URIs in {@code repository}; a class {@code href} must name a
     * file in the instance's folder or below it, or in one of {@code allowedDirs} or below.
     */
    public MissionLoader(PolicyRepository repository, List<Path> allowedDirs) {
        this.repository = java.util.Objects.requireNonNull(repository, "repository");
        this.allowedDirs = List.copyOf(allowedDirs);
    }

    /**
     * Loads and checks an instance file and its class file.
     *
     * @throws MissionException naming every error of both files (class file first)
     * @throws IOException      when the instance file itself cannot be read (an unreadable class
     *                          file is an error of the instance, reported in a MissionException)
     */
    public Mission load(Path instanceFile) throws MissionException, IOException {
        String text = xml.readFile(instanceFile);
        List<MissionError> instanceErrors = new ArrayList<>();
        List<MissionError> classErrors = new ArrayList<>();
        Reporter reporter = new Reporter(instanceFile, instanceErrors);
        XmlElement root = parse(text, reporter);
        InstanceSpec instance = root == null ? null : InstanceReader.read(root, reporter);
        ClassSpec spec = instance == null ? null : readClass(instanceFile, instance, reporter, classErrors);
        if (instance != null) {
            InstanceRules.check(instance, spec, new PolicyCheck(repository), reporter);
        }
        List<MissionError> errors = new ArrayList<>(byPosition(classErrors));
        errors.addAll(byPosition(instanceErrors));
        if (!errors.isEmpty()) {
            throw new MissionException(errors);
        }
        return build(spec, instance);
    }

    private ClassSpec readClass(Path instanceFile, InstanceSpec instance, Reporter reporter, List<MissionError> errors) {
        if (instance.classHref() == null) {
            return null;
        }
        String href = instance.classHref();
        Path classFile;
        try {
            classFile = instanceFile.resolveSibling(href).normalize();
        } catch (InvalidPathException e) {
            reporter.error(instance.classAt(), "invalid class file name '" + href + "'; <missionClass href> names a file");
            return null;
        }
        String outside = outsideAllowed(instanceFile, classFile);
        if (outside != null) {
            reporter.error(instance.classAt(), "refused mission class '" + href + "': " + outside
                    + "; <missionClass href> must name a file in the instance's folder or below, "
                    + "unless that folder is allowed explicitly");
            return null;
        }
        String problem = !Files.exists(classFile) ? "no such file"
                : !Files.isRegularFile(classFile) ? "not a regular file"
                : null;
        String text = null;
        if (problem == null) {
            try {
                text = xml.readFile(classFile);
            } catch (IOException e) {
                problem = String.valueOf(e.getMessage());
            }
        }
        if (problem != null) {
            reporter.error(instance.classAt(), "cannot read mission class '" + href + "': " + problem
                    + "; <missionClass href> names a mission class file relative to this instance");
            return null;
        }
        Reporter classReporter = new Reporter(classFile, errors);
        XmlElement root = parse(text, classReporter);
        ClassSpec spec = root == null ? null : ClassReader.read(root, classReporter);
        if (spec != null) {
            ClassRules.check(spec, classReporter);
        }
        return spec;
    }

    /**
     * Why {@code classFile} may not be opened, or null when it is in the instance's folder (or below)
     * or in an allowed folder; symbolic links are followed before the check.
     */
    private String outsideAllowed(Path instanceFile, Path classFile) {
        Path target;
        List<Path> roots = new ArrayList<>();
        try {
            target = Files.exists(classFile) ? classFile.toRealPath() : classFile.toAbsolutePath().normalize();
            Path folder = instanceFile.toAbsolutePath().getParent();
            roots.add(folder == null ? Path.of("").toAbsolutePath() : folder.toRealPath());
            for (Path dir : allowedDirs) {
                roots.add(Files.exists(dir) ? dir.toRealPath() : dir.toAbsolutePath().normalize());
            }
        } catch (IOException e) {
            return "its location cannot be checked (" + e.getClass().getSimpleName() + ")";
        }
        for (Path root : roots) {
            if (target.startsWith(root)) {
                return null;
            }
        }
        return "it is outside the instance's folder " + roots.get(0)
                + (roots.size() > 1 ? " and the allowed folders " + roots.subList(1, roots.size()) : "");
    }

    /** The root of a mission file's text, or {@code null} after reporting why it was refused. */
    private XmlElement parse(String text, Reporter reporter) {
        try {
            return xml.read(text);
        } catch (XmlRefusal e) {
            reporter.syntaxError(e.line(), e.column(), e.getMessage());
            return null;
        }
    }

    private static List<MissionError> byPosition(List<MissionError> errors) {
        List<MissionError> sorted = new ArrayList<>(errors);
        sorted.sort(Comparator.comparingInt(MissionError::line).thenComparingInt(MissionError::column));
        return sorted;
    }

    /** The mission both files describe; called only when no error was found. */
    private static Mission build(ClassSpec spec, InstanceSpec instance) {
        Map<String, String> primaryOf = new HashMap<>();
        spec.secondary().forEach(s -> primaryOf.put(s.role().name(), s.primary().name()));
        List<MissionRole> roles = new ArrayList<>();
        for (RoleDecl decl : spec.roles()) {
            RoleEntry entry = instance.role(decl.name());
            int minimal = decl.hasCardinality() ? entry.cardinality().minimal() : 1;
            int optimal = decl.hasCardinality() ? entry.cardinality().optimal() : 1;
            roles.add(new MissionRole(decl.name(), minimal, optimal, decl.manages().stream().map(Ref::name).toList(),
                    decl.requirement(), Optional.ofNullable(primaryOf.get(decl.name())),
                    entry.policies().stream().map(Ref::name).toList(),
                    entry.authorisations().stream().map(Ref::name).toList(), decl.interfaces()));
        }
        Colocation colocation = new Colocation(
                spec.parallel().stream().map(p -> new Colocation.Parallel(p.role().name(),
                        p.with().stream().map(Ref::name).toList())).toList(),
                spec.exclusive().stream().map(e -> new Colocation.Exclusive(
                        e.roles().stream().map(Ref::name).toList())).toList());
        Map<String, Parameter> parameters = new LinkedHashMap<>();
        for (ParamDecl decl : spec.parameters()) {
            String text = instance.parameters().stream().filter(v -> v.name().equals(decl.name())).findFirst()
                    .orElseThrow().text();
            parameters.put(decl.name(), new Parameter(decl.name(), decl.type(), decl.type().parse(text)));
        }
        try {
            return new Mission(spec.name(), instance.name(), roles, colocation, parameters);
        } catch (IllegalArgumentException e) {
            throw new IllegalStateException("mission files passed every check but do not make a mission: " + e.getMessage(), e);
        }
    }
}
