package net.smc.demo;

import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;

import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.ParameterException;

/** The folder a command's {@code --out} names: made if missing, a usage error naming it if it cannot be. */
final class OutFolder {
    private OutFolder() {
    }

    /**
     * {@code out} resolved against {@code workingDir}, made (with its parents) if missing, and
     * checked by writing a file in it and deleting it again: a folder the run could not write its
     * files in is refused before the run, not after it.
     *
     * @throws ParameterException if a file of that name is there, or the folder cannot be made or written in
     */
    static Path make(CommandSpec spec, Path workingDir, Object out) {
        if (out.toString().isEmpty()) {
            throw new ParameterException(spec.commandLine(), "--out is empty; it names the folder the files go to");
        }
        Path target = workingDir.resolve(out.toString());
        if (Files.exists(target) && !Files.isDirectory(target)) {
            throw new ParameterException(spec.commandLine(), "--out '" + out + "': not a directory (a file of that name is there)");
        }
        Path dir;
        try {
            dir = Files.createDirectories(target);
        } catch (IOException e) {
            throw new ParameterException(spec.commandLine(), "--out '" + out + "': cannot create the directory: " + reason(e));
        }
        try {
            Files.delete(Files.createTempFile(dir, ".smc-write-check", ".tmp"));
        } catch (IOException e) {
            throw new ParameterException(spec.commandLine(), "--out '" + out + "': cannot write files in it: " + reason(e));
        }
        return dir;
    }

    /**
     * What went wrong in words, naming the file: the reason the file system gave for a
     * {@link FileSystemException} (whose plain message is its file alone, for some), else the message.
     */
    static String reason(IOException e) {
        if (e instanceof NoSuchFileException n) {
            return "no such file or folder: " + n.getFile();
        }
        if (e instanceof AccessDeniedException a) {
            return "permission denied: " + a.getFile();
        }
        if (e instanceof java.nio.file.FileAlreadyExistsException f) {
            return "something of that name is there already: " + f.getFile();
        }
        if (e instanceof java.nio.file.NotDirectoryException f) {
            return "not a folder: " + f.getFile();
        }
        if (e instanceof FileSystemException f) {
            return (f.getReason() != null ? f.getReason() : e.getClass().getSimpleName()) + (f.getFile() == null ? "" : ": " + f.getFile());
        }
        return String.valueOf(e.getMessage());
    }
}
