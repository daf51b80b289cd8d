package net.smc.demo;

import java.util.concurrent.Callable;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.FutureTask;

/**
 * Runs a cell's work on a thread of its own with a large stack, so that deep recursion in
 * PonderTalk ends at the engine's call-depth limit rather than at the JVM's stack size.
 */
final class LargeStack {
    /** 256 MiB: far more than the engine's deepest allowed nesting needs. */
    static final long STACK_BYTES = 256L * 1024 * 1024;

    private LargeStack() {
    }

    /** Runs {@code body} on a new large-stack thread and waits for it; its exceptions pass through. */
    static <T> T call(Callable<T> body) throws Exception {
        FutureTask<T> task = new FutureTask<>(body);
        Thread thread = new Thread(null, task, "smc-cell", STACK_BYTES);
        thread.start();
        try {
            return task.get();
        } catch (InterruptedException e) {
            thread.interrupt();
            throw e;
        } catch (ExecutionException e) {
            Throwable cause = e.getCause();
            if (cause instanceof Exception exception) {
                throw exception;
            }
            if (cause instanceof Error error) {
                throw error;
            }
            throw e;
        }
    }
}
