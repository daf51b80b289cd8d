package net.smc.core.task;

/** A task whose interface names another task: describing it is an error. */
public class Mapper extends Task implements SurveyorI {
    @Override
    public void survey(String area) {
    }
}
