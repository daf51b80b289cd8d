package net.smc.core.role;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import net.smc.policy.api.DomainHandle;
import org.junit.jupiter.api.Test;

class RoleManagerIdempotenceTest {
    private final Fixture f = new Fixture();
    private final AtomicInteger tasksMade = new AtomicInteger();
    private final Explorer explorer = new Explorer();

    private Role.Builder surveyor() {
        return Role.builder("surveyor").mission(Fixture.printer("surveyor", "a")).task("Explorer", () -> {
            tasksMade.incrementAndGet();
            return explorer;
        });
    }

    @Test
    void loadingTwice_loadsNothingTheSecondTime() throws Exception {
        f.roles.load(surveyor().build());

        Loaded second = f.roles.load(surveyor().build());

        assertTrue(second.alreadyPresent(), second::toString);
    }

    @Test
    void loadingTwice_leavesOnePolicy_andItFiresOnce() throws Exception {
        f.roles.load(surveyor().build());
        f.roles.load(surveyor().build());

        assertEquals(1, ((DomainHandle) f.cell.resolve("root/role/surveyor/policy")).entries().size());
        f.go(3);
        assertEquals(List.of("a 3"), f.out);
    }

    @Test
    void loadingTwice_makesAndStartsTheTaskOnce() throws Exception {
        f.roles.load(surveyor().build());
        f.roles.load(surveyor().build());

        assertEquals(1, tasksMade.get());
        assertEquals(1, explorer.starts);
    }

    @Test
    void loadingARoleWithAnExtraFile_runsOnlyTheMissingFile() throws Exception {
        f.roles.load(surveyor().build());

        Loaded second = f.roles.load(surveyor().mission(Fixture.printer("surveyor", "b")).build());

        assertEquals(List.of("b"), second.sources());
        assertEquals(List.of("b"), second.policies());
        f.go(4);
        assertEquals(List.of("a 4", "b 4"), f.out);
    }

    @Test
    void theSameFileInTwoRoles_loadsForEach() throws Exception {
        PolicySource shared = PolicySource.text("shared", "root print: \"loaded\".");
        f.roles.load(Role.builder("surveyor").mission(shared).build());
        f.roles.load(Role.builder("relay").mission(shared).build());

        assertEquals(List.of("loaded", "loaded"), f.out);
    }
}
