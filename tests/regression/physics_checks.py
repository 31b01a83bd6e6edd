#!/usr/bin/env python3
"""Physics checks of whole runs that need no paper (issue "Touchdown dynamics", item 8).

  physics_checks.py --exe LANDYN --src SOURCE_DIR TEST

free_fall          before touchdown the mass centre follows the analytic trajectory (fixed scheme: its
                   closed form, within O(dt) of the analytic one; adaptive: the analytic one)
symmetric_landing  LC-1 (symmetric lander, vertical landing) stays symmetric to round-off
slow_landing       a landing too slow to reach any crush level crushes nothing and comes to rest
dt_convergence     fixed scheme: halving dt changes no crush length by more than 0.2 mm (LC-1 ... LC-4)
energy_audit       the energy audit closes to 0.1 % also at the fixed scheme's coarse step 4e-5 s (LC-3 and
                   the two decks of the integration issue): it audits the leapfrog's synchronised
                   kinetic energy with trapezoidal works, not the stored half-step velocities
peaks              LC-3: the stored interval-peak histories hold the summary's peaks exactly (overload,
                   footpad normal force, strut force), and the 1 ms samples alone miss them
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

import numpy as np
import h5py

FAILS = []


def check(cond, what):
    print(("ok:   " if cond else "FAIL: ") + what)
    if not cond:
        FAILS.append(what)


def run(exe, d, name, deck_text=None, deck_path=None, extra=(), status=0):
    """Runs landyn; it must exit with `status` (7: no touchdown, docs/exit_status.md)."""
    if deck_text is not None:
        deck_path = os.path.join(d, name + ".nml")
        with open(deck_path, "w") as f:
            f.write(deck_text)
    out = os.path.join(d, name + ".h5")
    p = subprocess.run([exe, deck_path, "-q", "-o", out] + list(extra), capture_output=True, text=True)
    if p.returncode != status:
        print(p.stdout, p.stderr)
        raise SystemExit("landyn exited %d on %s (expected %d)" % (p.returncode, name, status))
    return h5py.File(out, "r")


def t_free_fall(exe, src, d):
    # Lowest footpad 0.3 m above flat ground, 4 m/s down: touchdown when 0.3 = 4 t + g t^2 / 2.
    g, v0, h = 1.62, 4.0, 0.3
    t_td = (-v0 + np.sqrt(v0 ** 2 + 2 * g * h)) / g
    f = run(exe, d, "ff", "&simulation integrator = 'fixed', t_end = 0.1 /\n&initial_state clearance = 0.3 /\n")
    t = f["timeseries/time"][()]
    x = f["timeseries/body/mass_centre_position"][()]
    v = f["timeseries/body/velocity"][()]
    fn = f["timeseries/gears/normal_force"][()]
    pre = t < t_td - 1e-4
    check(pre.sum() > 50, "%d samples before touchdown at t = %.5f s" % (pre.sum(), t_td))
    # Semi-implicit Euler with constant g: z_n = z0 + v0 t_n + g t_n^2/2 + g t_n dt/2, i.e. the exact
    # trajectory with initial velocity v0 + g dt/2, whose velocity at t_n is v0 + g (t_n + dt/2): the
    # stored velocity v0 + g t_n synchronised to t_n (+ dt/2 g), which is what the samples hold.
    dt = 5e-6
    z_exact = x[0, 2] + v0 * t + 0.5 * g * t ** 2
    z_scheme = z_exact + 0.5 * g * t * dt
    err_v = np.max(np.abs(v[pre, 2] - (v0 + g * (t[pre] + 0.5 * dt))))
    err_z = np.max(np.abs(x[pre, 2] - z_scheme[pre]))
    err_z_exact = np.max(np.abs(x[pre, 2] - z_exact[pre]))
    check(err_v < 1e-9, "vertical velocity = v0 + g (t + dt/2) (max error %.2e m/s)" % err_v)
    check(err_z < 1e-9, "height = scheme's closed form z0 + v0 t + g t^2/2 + g t dt/2 (max error %.2e m)" % err_z)
    check(err_z_exact < 0.5 * g * t_td * dt * 1.01,
          "height within the O(dt) bound g t dt/2 = %.2e m of the analytic trajectory (error %.2e m)"
          % (0.5 * g * t_td * dt, err_z_exact))
    check(np.max(np.abs(x[pre, :2] - x[0, :2])) < 1e-12, "no horizontal motion")
    check(np.all(fn[pre] == 0.0), "no ground force before touchdown")
    first = t[np.argmax(fn.max(axis=1) > 0.0)]
    check(t_td <= first <= t_td + 1.0e-3 + 1e-9,
          "the first ground force appears within one output interval after touchdown (%.5f s)" % first)
    check(np.max(np.abs(f["timeseries/gears/stroke"][()][pre])) < 1e-12, "no stroke before touchdown")
    # The adaptive integrator (the default): variable-step leapfrog, exact for constant acceleration
    # with synchronised velocities; its steps grow to dt_max in free fall (run ends before touchdown).
    # ends in the air, before touchdown: outcome no_touchdown, exit status 7
    f = run(exe, d, "ff_adaptive", "&simulation t_end = 0.07 /\n&initial_state clearance = 0.3 /\n", status=7)
    check(f["summary/outcome/name"][()] == b"no_touchdown", "adaptive: the run that ends in the air is a no_touchdown")
    t = f["timeseries/time"][()]
    x = f["timeseries/body/mass_centre_position"][()]
    v = f["timeseries/body/velocity"][()]
    pre = t < t_td - 1e-4
    z_exact = x[0, 2] + v0 * t + 0.5 * g * t ** 2
    err_v = np.max(np.abs(v[pre, 2] - (v0 + g * t[pre])))
    err_z = np.max(np.abs(x[pre, 2] - z_exact[pre]))
    check(err_v < 1e-9, "adaptive: vertical velocity = v0 + g t (max error %.2e m/s)" % err_v)
    check(err_z < 1e-9, "adaptive: height = z0 + v0 t + g t^2/2 (max error %.2e m)" % err_z)
    check(f["summary/n_steps"][()] < 100,
          "adaptive: steps grow to dt_max = 1 ms, fewer than 100 steps for 0.07 s (%d; 14,000 at the paper's step)"
          % f["summary/n_steps"][()])


def t_thrust(exe, src, d):
    # Thrust equal to the weight (16000 kg x 1.62 m/s^2 = 25,920 N) along lander -z (up), cut off at
    # 0.05 s: the descent speed stays 4 m/s until the cut-off, then grows at g; touchdown from 0.4 m.
    f = run(exe, d, "thrust", "&simulation t_end = 0.12 /\n&initial_state clearance = 0.4 /\n"
                              "&engine thrust = 25920.0, direction = 0.0, 0.0, -1.0, cutoff_time = 0.05 /\n")
    t = f["timeseries/time"][()]
    v = f["timeseries/body/velocity"][()][:, 2]
    on = t < 0.05 - 1e-9
    check(np.max(np.abs(v[on] - 4.0)) < 1e-9, "hover thrust: constant 4 m/s descent (max change %.2e m/s)"
          % np.max(np.abs(v[on] - 4.0)))
    after = (t > 0.05 + 1e-9) & (t < 0.08)
    check(np.max(np.abs(v[after] - (4.0 + 1.62 * (t[after] - 0.05)))) < 2e-5,
          "after cut-off the speed grows at g (max error %.2e m/s)" % np.max(np.abs(v[after] - (4.0 + 1.62 * (t[after] - 0.05)))))
    w = f["timeseries/energy/thrust_work"][()]
    drop = 4.0 * 0.05   # metres descended under thrust
    check(abs(w[-1] + 25920.0 * drop) < 1e-3 * 25920.0 * drop,
          "thrust work = -T x distance descended under thrust (%.1f J vs %.1f J)" % (w[-1], -25920.0 * drop))
    check(abs(f["summary/energy_residual"][()]) < 0.001, "energy audit closes with thrust (%.4f %%)"
          % (100 * f["summary/energy_residual"][()]))


def t_symmetric_landing(exe, src, d):
    f = run(exe, d, "lc1", deck_path=os.path.join(src, "input", "lc1.nml"))
    c = f["summary/crush_length"][()]
    check(np.max(np.abs(c - c[0])) < 1e-9, "the four gears crush alike (spread %.2e m)" % np.max(np.abs(c - c[0])))
    check(np.max(np.abs(c[:, 1] - c[:, 2])) < 1e-9, "left and right secondaries crush alike (%.2e m)"
          % np.max(np.abs(c[:, 1] - c[:, 2])))
    s = f["timeseries/gears/stroke"][()]
    check(np.max(np.abs(s - s[:, :1, :])) < 1e-9, "stroke histories of the four gears agree to round-off (%.2e m)"
          % np.max(np.abs(s - s[:, :1, :])))
    e = f["timeseries/body/euler_angles"][()]
    check(np.max(np.abs(e)) < 1e-6, "attitude stays zero (max %.2e deg)" % np.max(np.abs(e)))
    x = f["timeseries/body/position"][()]
    check(np.max(np.abs(x[:, :2])) < 1e-9, "no horizontal drift (max %.2e m)" % np.max(np.abs(x[:, :2])))


def t_slow_landing(exe, src, d):
    # 0.05 m/s: the peak leg force is ~ v sqrt(k m)/4 ~ 25 kN, far below the 78 kN / 43 kN / 30 kN levels.
    f = run(exe, d, "slow", "&simulation t_end = 8.0, dt = 2.0e-5 /\n"
                            "&initial_state velocity = 0.0, 0.0, 0.05 /\n&output interval = 0.01 /\n")
    c = np.abs(f["summary/crushed_positive"][()]) + np.abs(f["summary/crushed_negative"][()])
    check(np.max(c) < 1e-9, "nothing crushes (largest crushed length %.2e m)" % np.max(c))
    reason = f["summary/end_reason"][()].decode()
    check(reason == "at rest", "the run ends at rest (end_reason '%s' at t = %.3f s)"
          % (reason, f["summary/final_time"][()]))
    check(int(f["summary/at_rest"][()]) == 1, "/summary/at_rest is set")
    # "At rest" is a speed criterion (rest_speed 1e-3 m/s for rest_time): the lander still bobs on
    # the soil springs with a period of ~0.3 s and a ground force +-10 % around its weight, so the
    # weight is carried on average over that period, and at the last sample with its inertial load.
    t = f["timeseries/time"][()]
    fsum = f["timeseries/gears/normal_force"][()].sum(axis=1)
    last = t > t[-1] - 0.3
    weight = 16000 * 1.62
    check(abs(fsum[last].mean() - weight) < 0.01 * weight,
          "over the last 0.3 s the footpads carry the lander's weight on average (%.1f N vs %.1f N)"
          % (fsum[last].mean(), weight))
    inertial = -16000 * 9.80665 * f["timeseries/body/overload"][()][-1, 2]   # M (g - a_z)
    check(abs(fsum[-1] - inertial) < 1e-6 * weight,
          "the final sample is an evaluated state: footpad forces = M (g - a) (%.3f N vs %.3f N)"
          % (fsum[-1], inertial))


def t_dt_convergence(exe, src, d):
    """Halving dt (5e-6 -> 2.5e-6 s) must change no crush length by more than 0.2 mm.

    Asserted for all four load cases. LC-2 used to miss (0.40 mm, 2026-11-22): the secondaries of
    the hopping lander chattered between crushing, locked and free in their crushed gap, and the
    small crush events of the second landing depended on round-off and dt. With velocity-level
    locking and the kinetic-metric impacts (docs/theory.md) it changes by 0.025 mm and its
    round-off spread fell from 0.19 mm to 8e-8 m.
    """
    for case, asserted in (("lc1", True), ("lc3", True), ("lc4", True), ("lc2", True)):
        deck = open(os.path.join(src, "input", case + ".nml")).read().replace("dt = 5.0e-6", "integrator = 'fixed', dt = 5.0e-6", 1)
        half = deck.replace("dt = 5.0e-6", "dt = 2.5e-6")
        check(half != deck, "the %s deck states dt = 5.0e-6" % case)
        a = run(exe, d, case + "_dt1", deck)
        b = run(exe, d, case + "_dt2", half)
        ca, cb = a["summary/crush_length"][()], b["summary/crush_length"][()]
        diff = 1000 * np.max(np.abs(ca - cb))
        print("%s: largest crush-length change on halving dt: %.3f mm" % (case.upper(), diff))
        if asserted:
            check(diff <= 0.2, "%s: halving dt changes no crush length by more than 0.2 mm (largest %.3f mm)"
                  % (case.upper(), diff))
        else:
            print("      %s: not asserted (known miss, docs/validation.md): %s 0.2 mm"
                  % (case.upper(), "within" if diff <= 0.2 else "EXCEEDS"))


def t_energy_audit(exe, src, d):
    # The scheme is the leapfrog: read with velocities at t_n - dt/2 and left-point works the
    # audit was off by ~0.27 % at 4e-5 s; read consistently it closes at every step size.
    decks = {
        "lc3": re.sub(r"\bdt\s*=\s*[0-9.eE+-]+", "integrator = 'fixed', dt = 4.0e-5",
                      open(os.path.join(src, "input", "lc3.nml")).read()),
        "deck_a": ("&simulation integrator = 'fixed', dt = 4.0e-5, t_end = 1.0 /\n"
                   "&terrain slope = 4*0.44, slope_direction = 4*0.0 /\n"
                   "&initial_state clearance = 0.0, velocity = 0.6, 0.0, 2.36, attitude = 2.83, -2.65, -4.72 /\n"),
        "deck_b": ("&simulation integrator = 'fixed', dt = 4.0e-5, t_end = 1.0 /\n"
                   "&initial_state velocity = 0, 0, 2.4, attitude = 0, -3, -5 /\n"),
    }
    for name, text in decks.items():
        f = run(exe, d, name, text)
        r = float(f["summary/energy_residual"][()])
        check(abs(r) <= 1e-3, "%s at dt = 4e-5 s: energy residual %.4f %% <= 0.1 %%" % (name, 100 * r))


def t_peaks(exe, src, d):
    h = run(exe, d, "lc3", deck_path=os.path.join(src, "input", "lc3.nml"))
    s = h["summary"]
    ts = h["timeseries"]
    ovl_peak = ts["body/overload_peak"][:]
    ovl_sampled = np.linalg.norm(ts["body/overload"][:], axis=1)
    print("LC-3 peak overload: summary %.4f g, stored peak channel %.4f g, 1 ms samples %.4f g"
          % (s["peak_overload"][()], ovl_peak.max(), ovl_sampled.max()))
    check(ovl_peak.max() == s["peak_overload"][()], "the overload peak channel holds the summary's peak overload")
    k = int(np.argmax(ovl_peak))
    check(abs(ts["time"][k] - s["time_of_peak_overload"][()]) <= 1.0e-3 + 1e-12,
          "the peak lies in the output interval that ends at the sample holding it")
    check(np.all(ovl_peak >= ovl_sampled * (1.0 - 1e-12)), "every interval peak is at least its sample (to round-off)")
    fn_peak = ts["gears/normal_force_peak"][:]
    fn_sampled = ts["gears/normal_force"][:]
    print("LC-3 peak normal force per footpad [kN]: summary %s, stored peak channel %s, 1 ms samples %s"
          % (np.round(s["peak_normal_force"][:] / 1e3, 1), np.round(fn_peak.max(axis=0) / 1e3, 1),
             np.round(fn_sampled.max(axis=0) / 1e3, 1)))
    check(np.array_equal(fn_peak.max(axis=0), s["peak_normal_force"][:]),
          "the normal-force peak channel holds the summary's peak normal force of every footpad")
    check(np.all(fn_peak >= fn_sampled), "every normal-force interval peak is at least its sample")
    check(np.array_equal(ts["gears/strut_force_peak"][:].max(axis=0), s["peak_strut_force"][:]),
          "the strut-force peak channel holds the summary's peak strut forces")
    check(fn_sampled.max() < s["peak_normal_force"][:].max(),
          "(the check has teeth: on LC-3 the 1 ms samples alone miss the peak normal force)")


TESTS = {k[2:]: v for k, v in globals().items() if k.startswith("t_")}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--exe", required=True)
    ap.add_argument("--src", required=True)
    ap.add_argument("test", choices=sorted(TESTS))
    a = ap.parse_args()
    with tempfile.TemporaryDirectory(prefix="landyn_phys_") as d:
        TESTS[a.test](os.path.abspath(a.exe), os.path.abspath(a.src), d)
    print("%d failed" % len(FAILS))
    sys.exit(1 if FAILS else 0)


if __name__ == "__main__":
    main()
