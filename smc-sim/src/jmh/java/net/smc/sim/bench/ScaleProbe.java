package net.smc.sim.bench;

/** Forms one team of each size given and prints simulated and wall time: a quick look, not a benchmark. */
public final class ScaleProbe {
    private static final int STEADY = Integer.getInteger("steady", 10);

    private ScaleProbe() {
    }

    public static void main(String[] args) {
        for (String a : args) {
            int n = Integer.parseInt(a);
            long t0 = System.nanoTime();
            ScaledTeam team = new ScaledTeam(n, 1, !Boolean.getBoolean("noInvariants"));
            long t1 = System.nanoTime();
            boolean ok = team.form();
            long t2 = System.nanoTime();
            System.out.printf("%d vehicles: built %.2f s, formed %s (%d seats) in %d ms simulated, %.2f s wall, at %d ms%n", n,
                    (t1 - t0) / 1e9, ok, team.acceptedSeats(), team.formationMillis(), (t2 - t1) / 1e9, team.sim.nowMillis());
            long[] before = new long[256];
            long[] beforeBytes = new long[256];
            for (int c = 0; c < 256; c++) {
                before[c] = team.datagrams(c);
                beforeBytes[c] = team.bytes(c);
            }
            long d = team.datagrams();
            long b = team.bytes();
            long t3 = System.nanoTime();
            team.sim.run(STEADY * 1000L);
            long t4 = System.nanoTime();
            System.out.printf("  steady %d s: %.1f datagrams/vehicle/s, %.1f B/vehicle/s, %.1f sim s per wall s%n", STEADY,
                    (team.datagrams() - d) / (double) STEADY / n, (team.bytes() - b) / (double) STEADY / n, STEADY / ((t4 - t3) / 1e9));
            for (int c = 0; c < 256; c++) {
                if (team.datagrams(c) > before[c]) {
                    System.out.printf("    type 0x%02x: %.2f datagrams/vehicle/s, %.1f B/vehicle/s, %.0f B each%n", c,
                            (team.datagrams(c) - before[c]) / (double) STEADY / n, (team.bytes(c) - beforeBytes[c]) / (double) STEADY / n,
                            (team.bytes(c) - beforeBytes[c]) / (double) (team.datagrams(c) - before[c]));
                }
            }
        }
    }
}
