package net.smc.policy.auth;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;

import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import net.smc.policy.api.AuthMode;
import net.smc.policy.PolicyEngine;
import net.smc.policy.api.Diagnostic;
import net.smc.policy.RunResult;
import net.smc.policy.runtime.Domain;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The authorisation decision of smc-policy/PONDERTALK.md section 9, one row per rule, each run through a real
 * cell. The boot unit builds two domain trees:
 *
 * <pre>
 * root/s1/s2/P   an obligation policy: on event go(v) its action does  T at: "k" put: v
 * root/t1/t2/T   the target domain
 * </pre>
 *
 * so the checked send is always {@code at:put:} from subject P to target T. A row installs its
 * authorisation policies, the boot phase ends (unless the row says otherwise), an optional later
 * unit changes things, then the event is raised and the row checks whether the put happened and
 * which errors were reported.
 */
class AuthorisationDecisionTest {

    private static final String SETUP = """
            s1 := root/factory/domain create. root at: "s1" put: s1.
            s2 := root/factory/domain create. s1 at: "s2" put: s2.
            t1 := root/factory/domain create. root at: "t1" put: t1.
            t2 := root/factory/domain create. t1 at: "t2" put: t2.
            T := root/factory/domain create. t2 at: "T" put: T.
            root/event at: "go" put: (root/factory/event create: #("v")).
            P := root/factory/ecapolicy create.
            s2 at: "P" put: P.
            P event: root/event/go; action: [:v | T at: "k" put: v].
            P active: true.
            """;

    /** Names every unit of a row can use. */
    private static final String NAMES = """
            s1 := root/s1. s2 := root/s1/s2. P := root/s1/s2/P.
            t1 := root/t1. t2 := root/t1/t2. T := root/t1/t2/T.
            """;

    private static final String DENIAL = "ObligationPolicy: unhandled action error: Ponder2AuthorizationException: at:put:";

    enum Trigger {
        /** The event is raised after the boot phase; P's action sends at:put: to T. */
        EVENT,
        /** The event is raised while the boot phase still runs. */
        EVENT_DURING_BOOT,
        /** A top-level statement (root as sender) sends at:put: to T after the boot phase. */
        TOP_LEVEL
    }

    record Row(String name, AuthMode mode, String policies, String later, Trigger trigger, int value, boolean stored,
               List<String> errors) {

        Row later(String text) {
            return new Row(name, mode, policies, text, trigger, value, stored, errors);
        }

        Row trigger(Trigger how) {
            return new Row(name, mode, policies, later, how, value, stored, errors);
        }

        Row value(int v) {
            return new Row(name, mode, policies, later, trigger, v, stored, errors);
        }

        /** The request ran but the reply was denied. */
        Row replyDenied() {
            return new Row(name, mode, policies, later, trigger, value, true, List.of(DENIAL));
        }

        Row errors(String... expected) {
            return new Row(name, mode, policies, later, trigger, value, stored, List.of(expected));
        }

        @Override
        public String toString() {
            return name;
        }
    }

    private static Row allowed(String name, AuthMode mode, String... policies) {
        return new Row(name, mode, String.join("", policies), "", Trigger.EVENT, 42, true, List.of());
    }

    private static Row denied(String name, AuthMode mode, String... policies) {
        return new Row(name, mode, String.join("", policies), "", Trigger.EVENT, 42, false, List.of(DENIAL));
    }

    /** An active authorisation policy for {@code action}, with modifiers such as {@code reqneg}. */
    private static String auth(String subject, String action, String target, String focus, String... modifiers) {
        StringBuilder text = new StringBuilder("a := root/factory/authpolicy subject: " + subject + " action: \"" + action
                + "\" target: " + target + " focus: \"" + focus + "\".\n");
        for (String m : modifiers) {
            text.append("a ").append(m).append(".\n");
        }
        return text.append("a active: true.\n").toString();
    }

    /** A positive policy for at:put:. */
    private static String pos(String subject, String target, String focus, String... modifiers) {
        return auth(subject, "at:put:", target, focus, modifiers);
    }

    /** A negative (reqneg) policy for at:put:. */
    private static String neg(String subject, String target, String focus, String... modifiers) {
        String[] all = Stream.concat(Stream.of("reqneg"), Stream.of(modifiers)).toArray(String[]::new);
        return auth(subject, "at:put:", target, focus, all);
    }

    /** Stores the policy just created (variable a) as root/policy/name. */
    private static String named(String name, String policy) {
        return policy + "root/policy at: \"" + name + "\" put: a.\n";
    }

    static Stream<Row> rows() {
        AuthMode deny = AuthMode.DENY;
        AuthMode allow = AuthMode.ALLOW;
        return Stream.of(
                // defaults
                denied("noPolicy_defaultDeny_denies", deny),
                allowed("noPolicy_defaultAllow_allows", allow),
                allowed("authOff_policiesAreNeverChecked", AuthMode.OFF, neg("root", "root", "st")),
                allowed("positiveAtRootRoot_bothSides_allowsUnderDefaultDeny", deny, pos("root", "root", "st")),
                denied("negativeAtRootRoot_deniesUnderDefaultAllow", allow, neg("root", "root", "t")),

                // domain nesting: the more specific normal policy decides
                denied("specificNegative_subjectS2TargetT2_overridesGeneralPositive", deny,
                        pos("root", "root", "st"), neg("s2", "t2", "st")),
                allowed("specificPositive_subjectS2TargetT2_overridesGeneralNegative", deny,
                        neg("root", "root", "st"), pos("s2", "t2", "st")),
                allowed("specificPositive_overridesGeneralNegative_underDefaultAllow", allow,
                        neg("root", "root", "st"), pos("s2", "t2", "st")),
                allowed("policyOnTheObjectsThemselves_isTheInnermostPair", deny,
                        neg("root", "root", "st"), neg("s2", "t2", "st"), pos("P", "T", "st")),
                allowed("subjectNestingDominates_innerSubjectOuterTargetBeatsOuterSubjectInnerTarget", deny,
                        neg("s1", "T", "st"), pos("s2", "root", "st")),
                denied("subjectNestingDominates_innerSubjectNegativeBeatsOuterSubjectPositive", allow,
                        pos("s1", "T", "st"), neg("s2", "root", "st")),
                denied("negativeAndPositiveAtTheSameLevel_negativeWins", allow,
                        pos("s1", "t1", "st"), neg("s1", "t1", "st")),
                denied("negativeAndPositiveAtTheSameLevel_negativeWinsWhicheverCameFirst", deny,
                        neg("s1", "t1", "st"), pos("s1", "t1", "st")),

                // final policies: outermost first, and they beat every normal policy
                allowed("outerFinalPositive_cannotBeOverriddenByAnInnerNegative", deny,
                        pos("root", "root", "st", "final"), neg("s2", "t2", "st")),
                denied("outerFinalNegative_beatsAnInnerPositive", allow,
                        neg("root", "root", "st", "final"), pos("s2", "t2", "st")),
                denied("outerFinalNegative_beatsAnInnerFinalPositive", allow,
                        neg("root", "root", "st", "final"), pos("s2", "t2", "st", "final")),
                allowed("outerFinalPositive_beatsAnInnerFinalNegative", deny,
                        pos("root", "root", "st", "final"), neg("s2", "t2", "st", "final")),
                denied("finalNegativeAndPositiveAtTheSameLevel_negativeWins", deny,
                        pos("s1", "t1", "st", "final"), neg("s1", "t1", "st", "final")),
                allowed("innerFinalPositive_beatsAnOuterNormalNegative", deny,
                        neg("root", "root", "st"), pos("s2", "t2", "st", "final")),
                denied("finalsRunSubjectMajor_rootToTBeforeS1ToRoot", allow,
                        pos("s1", "root", "st", "final"), neg("root", "T", "st", "final")),

                // which sends a policy matches
                allowed("starAction_matchesAtPut", deny, auth("root", "*", "root", "st")),
                denied("starAction_negativeDeniesAtPut", allow, auth("root", "*", "root", "st", "reqneg")),
                denied("positiveForAnotherAction_doesNotMatch", deny, auth("root", "at:", "root", "st")),
                allowed("negativeForAnotherAction_doesNotMatch", allow, auth("root", "remove:", "root", "st", "reqneg")),
                allowed("negativeForAnotherSubject_doesNotMatch", allow, neg("t1", "root", "st")),
                allowed("negativeForAnotherTarget_doesNotMatch", allow, neg("root", "s1", "st")),

                // focus: which enforcement points a policy applies at
                denied("focusTargetPositiveAlone_subjectSideStillTakesDefaultDeny", deny, pos("root", "root", "t")),
                denied("focusSubjectPositiveAlone_targetSideStillTakesDefaultDeny", deny, pos("root", "root", "s")),
                allowed("focusSubjectPositiveAndFocusTargetPositive_allow", deny,
                        pos("root", "root", "s"), pos("root", "root", "t")),
                denied("focusSubjectNegative_deniesAtTheSubjectEvenWhenTheTargetSideAllows", allow,
                        pos("s2", "t2", "t"), neg("root", "root", "s")),
                denied("focusTargetNegative_deniesAtTheTargetEvenWhenTheSubjectSideAllows", allow,
                        pos("s2", "t2", "s"), neg("root", "root", "t")),
                allowed("focusSubjectNegative_isNotSeenAtTheTargetSide", deny,
                        neg("s2", "t2", "s"), pos("P", "T", "s"), pos("root", "root", "t")),
                denied("focusST_negativeDenies", allow, neg("root", "root", "st")),

                // request conditions
                allowed("reqcondition_onTheSecondArgumentByPosition_true_policyApplies", deny,
                        pos("root", "root", "st", "reqcondition: [:key :val | val > 10]")).value(42),
                denied("reqcondition_onTheSecondArgumentByPosition_false_policyDoesNotApply", deny,
                        pos("root", "root", "st", "reqcondition: [:key :val | val > 10]")).value(5),
                allowed("reqcondition_firstArgumentIsTheKey", deny,
                        pos("root", "root", "st", "reqcondition: [:key | key == \"k\"]")),
                denied("reqcondition_onANegative_deniesWhenTrue", allow,
                        neg("root", "root", "st", "reqcondition: [:key :val | val > 10]")).value(42),
                allowed("reqcondition_onANegative_allowsWhenFalse", allow,
                        neg("root", "root", "st", "reqcondition: [:key :val | val > 10]")).value(5),
                allowed("reqcondition_pSubjectAndPTargetAreBoundByName", deny,
                        pos("root", "root", "st", "reqcondition: [:p_target :key :p_subject | "
                                + "(p_subject == P) & (p_target == T) & (key == \"k\")]")),
                allowed("reqcondition_pSubjectAndPTargetAreVisibleWithoutParameters", deny,
                        pos("root", "root", "st", "reqcondition: [:key :val | (p_subject == P) & (p_target == T)]")),
                denied("reqcondition_pSubjectMismatch_policyDoesNotApply", deny,
                        pos("root", "root", "st", "reqcondition: [:p_subject | p_subject == T]")),
                denied("reqcondition_thatFails_countsAsFalseAndIsReported", deny,
                        pos("root", "root", "st", "reqcondition: [:key :val | val frob]"))
                        .errors("AuthorisationPolicy: condition error: unknown operation 'frob' on Number", DENIAL),
                allowed("reqcondition_allConditionsMustHold", allow,
                        neg("root", "root", "st", "reqcondition: [:key :val | val > 10]",
                                "reqcondition: [:key :val | val < 20]")).value(42),

                // replies
                allowed("repneg_deniesTheReplyAfterTheRequestRan", deny, pos("root", "root", "st", "repneg"))
                        .replyDenied(),
                allowed("repcondition_trueOnTheResult_repnegDenies", allow,
                        auth("root", "at:put:", "root", "t", "repneg", "repcondition: [:result | result > 10]"))
                        .value(42).replyDenied(),
                allowed("repcondition_falseOnTheResult_repnegDoesNotApply", allow,
                        auth("root", "at:put:", "root", "t", "repneg", "repcondition: [:result | result > 10]"))
                        .value(5),
                allowed("repcondition_falseOnAPositive_replyTakesDefaultDeny", deny,
                        pos("root", "root", "st", "repcondition: [:result | result < 10]")).value(42).replyDenied(),
                allowed("reqcondition_isNotCheckedOnTheReply", deny, pos("root", "root", "st"),
                        auth("root", "at:put:", "root", "st", "repneg", "reqcondition: [:key | false]")).replyDenied(),

                // activation and changes at run time
                denied("inactivePolicy_isIgnored", deny,
                        "a := root/factory/authpolicy subject: root action: \"at:put:\" target: root focus: \"st\".\n"),
                denied("policyDeactivatedAfterBoot_noLongerAllows", deny, named("a1", pos("root", "root", "st")))
                        .later("root/policy/a1 active: false."),
                allowed("negativeDeactivatedAfterBoot_noLongerDenies", allow, named("a1", neg("root", "root", "st")))
                        .later("root/policy/a1 active: false."),
                allowed("policyAddedAfterBoot_changesTheDecision", deny).later(pos("root", "root", "st")),
                denied("subjectRemovedFromItsDomainAfterBoot_losesThatDomainsPolicies", deny, pos("s2", "t2", "st"))
                        .later("s2 remove: \"P\"."),

                // objects in several domains, or in none
                denied("targetInTwoDomains_onePathDenies_denies", deny,
                        "u := root/factory/domain create. root at: \"u\" put: u. u at: \"T\" put: T.\n",
                        pos("root", "t2", "st"), neg("root", "u", "st")),
                allowed("targetInTwoDomains_anAllowOnOnePathAllows", deny,
                        "u := root/factory/domain create. root at: \"u\" put: u. u at: \"T\" put: T.\n",
                        pos("root", "u", "st")),
                denied("subjectInTwoDomains_onePathDenies_denies", deny,
                        "v := root/factory/domain create. root at: \"v\" put: v. v at: \"P\" put: P.\n",
                        pos("s2", "root", "st"), neg("v", "root", "st")),
                denied("targetInSeventeenDomains_aDenyOnTheLastPathStillDenies", deny,
                        "17 do: [:i | d := root/factory/domain create. root at: \"d\" + i put: d. d at: \"T\" put: T].\n",
                        pos("root", "t2", "st"), neg("root", "root/d16", "st")),
                denied("targetNestedFortyDomainsDeep_isStillChecked", deny,
                        "h := #() asHash. h at: \"d\" put: t2.\n"
                        + "40 do: [:i | n := root/factory/domain create. (h at: \"d\") at: \"n\" put: n. h at: \"d\" put: n].\n"
                        + "t2 remove: \"T\". (h at: \"d\") at: \"T\" put: T.\n"),
                allowed("targetInNoDomain_isNeverChecked", deny, neg("root", "root", "st"), "t2 remove: \"T\".\n"),
                allowed("targetRemovedFromEveryDomainAfterBoot_isNoLongerChecked", deny, neg("root", "root", "st"))
                        .later("t2 remove: \"T\"."),

                // who is checked, and when
                allowed("topLevelStatements_rootAsSender_areNeverChecked", deny, neg("root", "root", "st"))
                        .trigger(Trigger.TOP_LEVEL),
                allowed("bootUnits_runWithDefaultAllowEvenInDenyMode", deny).trigger(Trigger.EVENT_DURING_BOOT),
                denied("bootUnits_stillApplyNegativePolicies", deny, neg("root", "root", "st"))
                        .trigger(Trigger.EVENT_DURING_BOOT));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("rows")
    void decision(Row row) {
        List<Diagnostic> reported = new ArrayList<>();
        PolicyEngine cell = PolicyEngine.builder().auth(row.mode()).errors(reported::add).build();
        mustRun(cell, "setup.p2", SETUP, reported);
        Domain target = assertInstanceOf(Domain.class, cell.resolve("root/t1/t2/T"));
        mustRun(cell, "policies.p2", NAMES + row.policies(), reported);
        if (row.trigger() != Trigger.EVENT_DURING_BOOT) {
            cell.endBoot();
        }
        if (!row.later().isEmpty()) {
            mustRun(cell, "later.p2", NAMES + row.later(), reported);
        }
        if (row.trigger() == Trigger.TOP_LEVEL) {
            cell.run("top.p2", "root/t1/t2/T at: \"k\" put: " + row.value());
        } else {
            cell.raise("root/event/go", row.value());
        }
        Object stored = target.get("k");
        List<String> messages = reported.stream().map(Diagnostic::message).toList();
        assertEquals(row.stored(), stored != null, row.name() + ": whether the put happened; reported " + messages);
        if (row.stored()) {
            assertEquals(String.valueOf(row.value()), PolicyEngine.print(stored), row.name() + ": the stored value");
        }
        assertEquals(row.errors(), messages, row.name() + ": reported errors");
    }

    private static void mustRun(PolicyEngine cell, String name, String text, List<Diagnostic> reported) {
        RunResult result = cell.run(name, text);
        assertEquals(List.of(), reported, "errors of " + name);
        assertEquals(RunResult.Status.OK, result.status(), name);
    }
}
