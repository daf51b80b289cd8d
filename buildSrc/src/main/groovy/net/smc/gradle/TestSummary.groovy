package net.smc.gradle

import org.gradle.api.DefaultTask
import org.gradle.api.GradleException
import org.gradle.api.tasks.TaskAction

/**
 * Judges every JUnitConsole run of this build from its legacy XML reports and exit code: prints
 * each failure with a short stack, then fails the build if a test failed or a test JVM did not
 * finish normally. The closing "tests: N passed, M failed" line is left to the build script,
 * which prints it after Gradle's own failure report so that it really is the last line.
 */
class TestSummary extends DefaultTask {
    int passed, failed, skipped
    /** Set once this task has run; null when no tests ran in this build. */
    String summaryLine

    TestSummary() {
        outputs.upToDateWhen { false }
    }

    @TaskAction
    void summarize() {
        // In execution order, so the failures read in the order they happened.
        def runs = project.gradle.taskGraph.allTasks.findAll { it instanceof JUnitConsole }
        runs.each { summarizeRun(it) }
        summaryLine = "tests: $passed passed, $failed failed" + (skipped > 0 ? ", $skipped skipped" : '')
        if (failed > 0) {
            throw new GradleException("$failed failure${failed == 1 ? '' : 's'} in the tests (listed above)")
        }
    }

    void summarizeRun(JUnitConsole run) {
        String module = run.project.path == ':' ? 'scenarios' : run.project.name
        String logPath = project.rootProject.relativePath(run.outputLog)
        if (!run.state.executed || !run.exitCodeFile.file) {
            jvmProblem(module, 'tests did not run (an earlier task failed)', null)
            return
        }
        int exitCode = run.exitCodeFile.text.trim() as int
        List<File> reports = run.reportsDir.listFiles().findAll { it.name ==~ /TEST-.*\.xml/ }
        if (reports.empty) {
            if (exitCode != 0 || run.outputLog.file) {
                jvmProblem(module, "test JVM ended with exit code $exitCode and wrote no report", run.outputLog)
            }
            return
        }
        int failedBefore = failed
        for (File report : reports) {
            try {
                countReport(module, new XmlSlurper().parse(report))
            } catch (Exception e) {
                jvmProblem(module, "unreadable report ${report.name} ($e.message)", run.outputLog)
            }
        }
        // 0: all passed, 1: something failed. Anything else means the JVM itself died.
        if (exitCode > 1) {
            jvmProblem(module, "test JVM crashed (exit code $exitCode)", run.outputLog)
        } else if (exitCode == 1 && failed == failedBefore) {
            // e.g. a test class that cannot even be loaded: the launcher counts it, the XML may not
            jvmProblem(module, 'the launcher reported a failure outside any test case', run.outputLog)
        } else if (failed > failedBefore) {
            println "    (full test output: $logPath)"
        }
    }

    void countReport(String module, report) {
        report.'**'.findAll { it.name() == 'testcase' }.each { tc ->
            def problem = tc.failure.size() ? tc.failure : tc.error
            if (problem.size()) {
                failed++
                println ''
                println "FAILED [$module] ${tc.@classname} > ${tc.@name}"
                shortTrace(problem.text() ?: "${problem.@type}: ${problem.@message}").each { println it }
            } else if (tc.skipped.size()) {
                skipped++
            } else {
                passed++
            }
        }
    }

    void jvmProblem(String module, String what, File log) {
        failed++
        println ''
        println "FAILED [$module] $what"
        if (log?.file) {
            // The cause is often at the top (bad option, missing class), the crash at the bottom.
            def lines = log.readLines()
            def shown = lines.size() <= 30 ? lines : lines.take(10) + ['...'] + lines.takeRight(19)
            println "    from ${project.rootProject.relativePath(log)}:"
            shown.each { println "    | $it" }
        }
    }

    /** The exception lines, the frame that threw (unless an assertion), and frames outside JUnit and the JDK. */
    static List<String> shortTrace(String trace) {
        def out = []
        boolean firstFrame = false
        int shownFrames = 0
        for (String line : trace.readLines()) {
            String t = line.trim()
            if (t.isEmpty() || t ==~ /\.\.\. \d+ more/) continue
            if (!t.startsWith('at ')) {        // "Type: message", "Caused by: ...", message lines
                out << '    ' + t
                firstFrame = true
                shownFrames = 0
            } else if (((firstFrame && !t.startsWith('at org.junit.')) || !isFramework(t)) && shownFrames < 6) {
                out << '        ' + t
                firstFrame = false
                shownFrames++
            }
            if (out.size() >= 40) {
                out << '    ...'
                break
            }
        }
        out
    }

    static boolean isFramework(String frame) {
        ['at org.junit.', 'at java.base/', 'at jdk.internal.', 'at java.lang.reflect.', 'at sun.reflect.']
                .any { frame.startsWith(it) }
    }
}
