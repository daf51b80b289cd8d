package net.smc.gradle

import org.gradle.api.DefaultTask
import org.gradle.api.file.FileCollection
import org.gradle.api.tasks.Classpath
import org.gradle.api.tasks.InputFiles
import org.gradle.api.tasks.TaskAction

/**
 * Runs one project's JUnit 5 tests in a fresh JVM through the JUnit Platform ConsoleLauncher:
 * Gradle 4.4's own Test task predates the JUnit Platform.
 *
 * It never fails the build over a test result: it keeps the launcher's exit code beside the XML
 * reports and TestSummary judges every run at the end, so one module's failures do not stop the
 * others from running.
 */
class JUnitConsole extends DefaultTask {
    /**
     * Test runtime classpath; must hold junit-platform-console. Declared as an input so that Gradle
     * builds what it holds (the jars of the modules under test) before the tests run.
     */
    @Classpath
    FileCollection classpath
    /** Directories scanned for test classes. */
    @InputFiles
    FileCollection testClassesDirs
    File reportsDir
    List<String> jvmArgs = []
    Map<String, Object> systemProperties = [:]
    Map<String, Object> environment = [:]
    /** Extra ConsoleLauncher options (filters and the like). */
    List<String> launcherArgs = []

    JUnitConsole() {
        // Reports from an earlier run must never stand in for this one (a crash would look fine).
        outputs.upToDateWhen { false }
    }

    /** Everything the test JVM printed; kept out of the console so the summary stays readable. */
    File getOutputLog() { new File(reportsDir, 'output.log') }

    File getExitCodeFile() { new File(reportsDir, 'exit-code') }

    @TaskAction
    void runTests() {
        project.delete(reportsDir)
        reportsDir.mkdirs()
        def scanDirs = testClassesDirs.files.findAll { it.directory }
        if (scanDirs.empty) {  // no test sources: nothing to run, and nothing went wrong
            exitCodeFile.text = '0'
            return
        }
        def cp = classpath
        def launcherCommand = ['execute', '--disable-banner', '--disable-ansi-colors', '--details=none',
                    '--reports-dir', reportsDir.absolutePath,
                    '--scan-classpath', scanDirs*.absolutePath.join(File.pathSeparator)] + launcherArgs
        def result = null
        outputLog.withOutputStream { out ->
            result = project.javaexec {
                main = 'org.junit.platform.console.ConsoleLauncher'
                classpath = cp
                jvmArgs = this.jvmArgs
                systemProperties = this.systemProperties
                environment this.environment
                args = launcherCommand
                standardOutput = out
                errorOutput = out
                ignoreExitValue = true
            }
        }
        exitCodeFile.text = result.exitValue as String
    }
}
