package net.smc.sim.experiment;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import net.smc.core.role.PolicySource;
import net.smc.core.role.Role;
import net.smc.core.role.RoleLoadException;
import net.smc.core.role.RoleManager;
import net.smc.policy.PolicyEngine;
import net.smc.policy.RunResult;

/**
 * What a vehicle's CPU does when it takes a role of a generated mission: its engine was booted when
 * the vehicle started; the role manager creates the role's domains and runs the role-mission and
 * authorisation files it downloaded. {@link #loadAndWithdraw} loads the role into one booted engine
 * and withdraws it again, so it can be timed over and over: by {@link Calibration} (per byte of the
 * two files) and by the JMH benchmark of role loading.
 */
public final class RoleLoadWork {
    private final RoleManager roles;
    private final Role role;
    private final int bytes;

    /**
     * @param bootEvents the project's {@code policies/boot/events.p2}
     * @param mission    a generated mission; its first role (a manager) is the one loaded
     */
    public RoleLoadWork(Path bootEvents, GeneratedMission mission) throws IOException {
        RoleType manager = mission.roles().get(0);
        Path dir = mission.repository().resolve("roles/" + manager.name());
        String text = Files.readString(dir.resolve("mission.p2"));
        String auth = Files.readString(dir.resolve("auth.p2"));
        this.bytes = text.length() + auth.length();
        this.role = Role.builder(manager.name()).mission(PolicySource.text("mission.p2", text))
                .authorisation(PolicySource.text("auth.p2", auth)).build();
        PolicyEngine engine = PolicyEngine.builder().build();
        check(engine.run("boot", Files.readString(bootEvents)));
        // Stands for the cell's discovery object, which the role's authorisations name as their target.
        check(engine.run("discovery", "root at: \"discovery\" put: root/factory/domain create."));
        this.roles = RoleManager.builder(engine).build();
    }

    /** Loads the role and withdraws it. */
    public void loadAndWithdraw() throws RoleLoadException {
        roles.load(role);
        roles.withdraw(role.name());
    }

    /** Bytes of policy text the role's files hold (what its policy replies carried). */
    public int bytes() {
        return bytes;
    }

    private static void check(RunResult r) {
        if (!r.ok()) {
            throw new IllegalStateException("role load set-up failed: " + r.diagnostics());
        }
    }
}
