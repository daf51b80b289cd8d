package net.smc.core.message;

import java.nio.charset.StandardCharsets;
import java.util.zip.Adler32;

/**
 * The preset dictionary with which policy texts are deflated ({@link WireFormat#POLICY_TEXT_DEFLATE_DICTIONARY}):
 * PonderTalk's vocabulary and the phrases this architecture's policy files are written in (the
 * factories, the event templates of {@code policies/boot/events.p2} and their attributes, the
 * obligation policies of the paper's Tables I and II, the authorisations that let a role's
 * policies use discovery and its manager use the role). A role's file of a few hundred bytes
 * gives DEFLATE too little of its own to refer back to; with the dictionary in front of it, its
 * first {@code root/factory/ecapolicy create} is already a back-reference. On a radio where a
 * manager sends every new child its files, those bytes are airtime.
 *
 * <p>The dictionary is part of the wire format: a zlib stream names it by its Adler-32
 * ({@link #ID}, RFC 1950's DICTID), and a receiver inflates only a stream that names this one.
 * Changing a byte of it changes {@link #ID} and so makes a new wire format; {@code
 * PolicyTextCodingTest} pins it. Phrases that recur most come last, nearest the text (DEFLATE's
 * distances are cheaper there).
 */
final class PolicyDictionary {
    /** The dictionary's UTF-8 bytes. */
    static final byte[] BYTES = """
            // Role-mission of the role: it manages the roles below it in the management tree.
            // Authorisations of the role: its own policies may use discovery; the manager may use its tasks.
            timesRepeat: whileTrue: [ do: [:each | collect: [:x | select: [:x | reject: detect: inject: into: [:acc |
             isNil notNil printString size remove: value: value ~= <= >= ^ self nil true false
            root/team invoke: root/print: #( ) ifTrue: [
            /event/handover /event/missionState /event/linkQuality /event/remoteResult /event/targetSighted
            /event/mapUpdate /event/inspected /event/areaExplored /event/hazardAdded /event/failedBody
            /event/wounded /event/distress /event/hazardDetected
             :name :uav :lowLevelCap :credential :role :state :kind :x :y
            (root/event has: "") ifFalse: [
                root/event at: "" put: (root/factory/event create: #("name" "uav" "role" "state"))].
             active: true.
             action: "create:"
             action: "*"
                    target: root/role/ /task focus: "st".
            (root/role/ /peers has: "") ifFalse: [
                root/role/ /peers at: "" put: root/factory/domain create].
            a := root/factory/authpolicy subject: root/role/ /peers/ action: "*"
                    target: root/role/ focus: "st".
            a := root/factory/authpolicy subject: root/role/ /policy action: "reassign:scheme:"
                    target: root/role/ focus: "st".
            a := root/factory/authpolicy subject: root/role/ /policy action: "fullCapReq:role:"
                    target: root/discovery focus: "st".
            a := root/factory/authpolicy subject: root/role/ /policy action: "uav:has:cap:auth:"
                    target: root/discovery focus: "st".
            root/role/ /auth at: "" put: a.
             := root/factory/ecapolicy create.
             event: /event/UAVFailure;
                condition: [:role | role == ""];
                action: [:name :role |
                    root print: "Received event:" + name + " (" + role + ")".
                    root/role/ reassign: role scheme: "default"].
             := root/factory/ecapolicy create.
             event: /event/newUAV;
                condition: [:lowLevelCap :uav :credential |
                    root/discovery uav: uav has: #("motion" "") cap: lowLevelCap auth: credential];
                action: [:name :uav |
                    root print: "Received event:" + name.
                    root/discovery fullCapReq: uav role: ""].
            root/role/ /policy at: "" put:\s
            """.getBytes(StandardCharsets.UTF_8);

    /** The dictionary's Adler-32, as a zlib stream deflated with it names it. */
    static final int ID = adler32(BYTES);

    private PolicyDictionary() {
    }

    private static int adler32(byte[] b) {
        Adler32 a = new Adler32();
        a.update(b);
        return (int) a.getValue();
    }
}
