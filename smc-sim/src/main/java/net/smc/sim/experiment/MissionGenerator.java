package net.smc.sim.experiment;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Objects;

import net.smc.core.cell.Scheme;

/**
 * Writes a mission class, its two instances (distributed and centralised) and a policy repository
 * for a mission of any number of roles in a management tree of a given depth (the set-up of the
 * paper's section V: "the number and types of roles are changed in the mission class
 * specification"). The tree is a {@link TreeShape}; each role type has a role-mission and an
 * authorisation policy file of its own:
 * <ul>
 *   <li>a manager's role-mission holds, per role it manages, a Table I style assignment policy
 *       ({@code newUAV}: the vehicle has the role's kit, then {@code fullCapReq:role:}) and a Table II
 *       style re-assignment policy; a leaf's holds a small policy of its own work;</li>
 *   <li>the commander's role-mission is per scheme: distributed, it assigns the level-1 roles;
 *       centralised, every role (as {@code policies/roles/commander/flat.p2} does for the
 *       reconnaissance).</li>
 * </ul>
 * Every vehicle has the resource {@code radio}; a role requires {@code kit_ROLE} as well, so each
 * vehicle fits exactly one role.
 *
 * <pre>{@code
 * GeneratedMission m = MissionGenerator.write(TreeShape.of(1000, 4), dir, Path.of("policies/boot/events.p2"));
 * Mission mission = new MissionLoader(new PolicyRepository(m.repository())).load(m.instanceFile(Scheme.DISTRIBUTED));
 * }</pre>
 */
public final class MissionGenerator {
    static final String RADIO = "radio";
    private static final String HEADER = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";

    private MissionGenerator() {
    }

    /** The generated missions' {@code comTimeout} (heartbeat period), ms; {@code failureTimeout} is six of it. */
    public static final long COM_TIMEOUT_MILLIS = 500;

    /**
     * Writes the mission of {@code shape} into {@code directory} (created if missing; files of an
     * earlier mission there are overwritten).
     *
     * @param bootEvents the boot file every cell runs first ({@code policies/boot/events.p2}), copied
     *                   into the generated repository
     */
    public static GeneratedMission write(TreeShape shape, Path directory, Path bootEvents) throws IOException {
        return write(shape, directory, bootEvents, COM_TIMEOUT_MILLIS);
    }

    /**
     * As {@link #write(TreeShape, Path, Path)}, with the mission parameter {@code comTimeout} (the
     * heartbeat period) {@code comTimeoutMillis} instead of {@value #COM_TIMEOUT_MILLIS}, and
     * {@code failureTimeout} six of it, as by default.
     *
     * @throws IllegalArgumentException when {@code comTimeoutMillis} is not from 1 to 60,000
     */
    public static GeneratedMission write(TreeShape shape, Path directory, Path bootEvents, long comTimeoutMillis)
            throws IOException {
        Objects.requireNonNull(shape, "shape");
        if (comTimeoutMillis < 1 || comTimeoutMillis > 60_000) {
            throw new IllegalArgumentException("comTimeout " + comTimeoutMillis + " ms must be from 1 to 60000");
        }
        if (!Files.isRegularFile(bootEvents)) {
            throw new IllegalArgumentException("boot policy file " + bootEvents + " does not exist; it must be the project's "
                    + "policies/boot/events.p2");
        }
        GeneratedMission mission = new GeneratedMission(directory, shape, roles(shape));
        Path policies = mission.repository();
        Files.createDirectories(policies.resolve("boot"));
        Files.copy(bootEvents, policies.resolve("boot/events.p2"), java.nio.file.StandardCopyOption.REPLACE_EXISTING);
        Files.createDirectories(mission.classFile().getParent());
        Files.writeString(mission.classFile(), classXml(mission));
        for (Scheme scheme : Scheme.values()) {
            Files.writeString(mission.instanceFile(scheme), instanceXml(mission, scheme, comTimeoutMillis));
            write(policies.resolve("roles/commander/" + schemeName(scheme) + ".p2"),
                    managerMission("commander", mission.managedBy("commander", scheme)));
        }
        write(policies.resolve("roles/commander/auth.p2"), auth("commander", null));
        for (RoleType r : mission.roles()) {
            List<RoleType> managed = mission.managedBy(r.name(), Scheme.DISTRIBUTED);
            write(policies.resolve("roles/" + r.name() + "/mission.p2"),
                    managed.isEmpty() ? leafMission(r) : managerMission(r.name(), managed));
            write(policies.resolve("roles/" + r.name() + "/auth.p2"), auth(r.name(), r.manager()));
        }
        return mission;
    }

    /** The scheme's name as a mission parameter and in file names. */
    static String schemeName(Scheme scheme) {
        return scheme.name().toLowerCase(Locale.ROOT);
    }

    private static List<RoleType> roles(TreeShape shape) {
        int[][] seats = shape.seatsPerBranch();
        List<RoleType> roles = new ArrayList<>();
        for (int level = 1; level < shape.depth(); level++) {
            for (int b = 0; b < seats.length; b++) {
                if (seats[b][level] > 0) {
                    String manager = level == 1 ? "commander" : "b" + b + "l" + (level - 1);
                    roles.add(new RoleType("b" + b + "l" + level, level, seats[b][level], manager));
                }
            }
        }
        return roles;
    }

    private static void write(Path file, String text) throws IOException {
        Files.createDirectories(file.getParent());
        Files.writeString(file, text);
    }

    // ---------------------------------------------------------------- XML

    private static String classXml(GeneratedMission m) {
        StringBuilder x = new StringBuilder(HEADER);
        x.append("<!--Generated: ").append(m.seats()).append(" roles in a management tree of depth ")
                .append(m.shape().depth()).append(", fan-out ").append(m.shape().fanOut()).append("-->\n");
        x.append("<xml>\n  <missionClassParameters>\n    <missionClassName>Generated</missionClassName>\n")
                .append("  </missionClassParameters>\n  <constraints/>\n  <missionParameters>\n")
                .append("    <comTimeout>int</comTimeout>\n    <failureTimeout>int</failureTimeout>\n")
                .append("    <scheme>string</scheme>\n    <backups>int</backups>\n  </missionParameters>\n");
        behaviour(x, "commander", null, m.managedBy("commander", Scheme.DISTRIBUTED));
        for (RoleType r : m.roles()) {
            behaviour(x, r.name(), r, m.managedBy(r.name(), Scheme.DISTRIBUTED));
        }
        return x.append("</xml>\n").toString();
    }

    private static void behaviour(StringBuilder x, String name, RoleType role, List<RoleType> managed) {
        x.append("  <").append(name).append("Behaviour>\n");
        if (role != null) {
            x.append("    <cardinality>int</cardinality>\n");
        }
        x.append("    <requires>\n      <resource>").append(RADIO).append("</resource>\n");
        if (role != null) {
            x.append("      <resource>").append(role.resource()).append("</resource>\n");
        }
        x.append("    </requires>\n");
        if (managed.isEmpty()) {
            x.append("    <roleManagement/>\n");
        } else {
            x.append("    <roleManagement>\n");
            managed.forEach(r -> x.append("      <manages>").append(r.name()).append("</manages>\n"));
            x.append("    </roleManagement>\n");
        }
        x.append("  </").append(name).append("Behaviour>\n");
    }

    private static String instanceXml(GeneratedMission m, Scheme scheme, long comTimeoutMillis) {
        String s = schemeName(scheme);
        StringBuilder x = new StringBuilder(HEADER);
        x.append("<xml>\n  <missionInstanceParameters>\n    <missionInstanceName>Generated").append(m.seats())
                .append(scheme == Scheme.CENTRALISED ? "Flat" : "").append("</missionInstanceName>\n")
                .append("    <missionClass href=\"generated.class.xml\">Generated</missionClass>\n")
                .append("  </missionInstanceParameters>\n  <missionParameters>\n")
                .append("    <comTimeout>").append(comTimeoutMillis).append("</comTimeout>\n    <failureTimeout>")
                .append(6 * comTimeoutMillis).append("</failureTimeout>\n")
                .append("    <scheme>").append(s).append("</scheme>\n    <backups>1</backups>\n")
                .append("  </missionParameters>\n");
        x.append("  <commander>\n    <policy>policy:/roles/commander/").append(s).append("</policy>\n")
                .append("    <authorisation>policy:/roles/commander/auth</authorisation>\n  </commander>\n");
        for (RoleType r : m.roles()) {
            x.append("  <").append(r.name()).append(">\n    <cardinality>\n      <minimal>").append(r.seats())
                    .append("</minimal>\n      <optimal>").append(r.seats()).append("</optimal>\n    </cardinality>\n")
                    .append("    <policy>policy:/roles/").append(r.name()).append("/mission</policy>\n")
                    .append("    <authorisation>policy:/roles/").append(r.name()).append("/auth</authorisation>\n")
                    .append("  </").append(r.name()).append(">\n");
        }
        return x.append("</xml>\n").toString();
    }

    // ---------------------------------------------------------------- PonderTalk

    /** Table I and II style policies of a role that manages {@code managed}. */
    private static String managerMission(String role, List<RoleType> managed) {
        StringBuilder p = new StringBuilder();
        p.append("// Role-mission of ").append(role).append(" (generated): it finds a vehicle for each role it manages\n")
                .append("// (newUAV: the vehicle has the role's kit; then its full capability description is asked for)\n")
                .append("// and has a failed holder's role re-assigned.\n\n");
        for (RoleType r : managed) {
            String n = r.name();
            p.append("assign := root/factory/ecapolicy create.\n")
                    .append("assign event: /event/newUAV;\n")
                    .append("    condition: [:lowLevelCap :uav :credential |\n")
                    .append("        root/discovery uav: uav has: #(\"").append(r.resource()).append("\") cap: lowLevelCap auth: credential];\n")
                    .append("    action: [:uav | root/discovery fullCapReq: uav role: \"").append(n).append("\"].\n")
                    .append("root/role/").append(role).append("/policy at: \"assign_").append(n).append("\" put: assign.\n\n")
                    .append("reassign := root/factory/ecapolicy create.\n")
                    .append("reassign event: /event/UAVFailure;\n")
                    .append("    condition: [:role | role == \"").append(n).append("\"];\n")
                    .append("    action: [:role | root/role/").append(role).append(" reassign: role scheme: \"default\"].\n")
                    .append("root/role/").append(role).append("/policy at: \"reassign_").append(n).append("\" put: reassign.\n\n");
        }
        return p.toString();
    }

    /** A leaf's role-mission: it counts the hazards reported to it. */
    private static String leafMission(RoleType r) {
        String n = r.name();
        return "// Role-mission of " + n + " (generated): a leaf of the management tree; it counts hazards.\n\n"
                + "root/role/" + n + " at: \"hazards\" put: 0.\n"
                + "seen := root/factory/ecapolicy create.\n"
                + "seen event: /event/hazardDetected;\n"
                + "    action: [:kind | root/role/" + n + " at: \"hazards\" put: (root/role/" + n + "/hazards) + 1].\n"
                + "root/role/" + n + "/policy at: \"countHazards\" put: seen.\n";
    }

    /** Authorisations as the reconnaissance roles have them: own policies use discovery; the manager uses the role. */
    private static String auth(String role, String manager) {
        StringBuilder a = new StringBuilder("// Authorisations of " + role + " (generated).\n\n");
        for (String op : List.of("uav:has:cap:auth:", "fullCapReq:role:")) {
            a.append("a := root/factory/authpolicy subject: root/role/").append(role).append("/policy action: \"")
                    .append(op).append("\"\n        target: root/discovery focus: \"st\".\n")
                    .append("root/role/").append(role).append("/auth at: \"").append(op.substring(0, op.indexOf(':')))
                    .append("\" put: a.\n");
        }
        a.append("a := root/factory/authpolicy subject: root/role/").append(role)
                .append("/policy action: \"reassign:scheme:\"\n        target: root/role/").append(role)
                .append(" focus: \"st\".\n").append("root/role/").append(role).append("/auth at: \"reassign\" put: a.\n");
        if (manager != null) {
            a.append("(root/role/").append(role).append("/peers has: \"").append(manager).append("\") ifFalse: [\n")
                    .append("    root/role/").append(role).append("/peers at: \"").append(manager)
                    .append("\" put: root/factory/domain create].\n")
                    .append("a := root/factory/authpolicy subject: root/role/").append(role).append("/peers/").append(manager)
                    .append(" action: \"*\"\n        target: root/role/").append(role).append(" focus: \"st\".\n")
                    .append("root/role/").append(role).append("/auth at: \"managerManages\" put: a.\n");
        }
        return a.toString();
    }
}
