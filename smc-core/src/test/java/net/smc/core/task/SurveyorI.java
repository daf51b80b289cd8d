package net.smc.core.task;

/** A task interface for the task Surveyor; {@link Mapper} implements it by mistake. */
@TaskInterface("Surveyor")
public interface SurveyorI {
    void survey(String area);
}
