#!/usr/bin/env python3
"""Independent reference of the headlight-leveling servo in models/.

This script integrates the *same equations* as the VHDL-AMS models in
models/*.vhd (dc_motor, constant_friction, gear_inertia, rack_pinion_gear,
spring, reflector_mass, potentiometer, wiring_harness, dashboard_pot, battery,
diode, hbridge_ic, headlight_system) with the same default parameters, written
independently of the vams simulator.  It exists so that the simulator's results
for tb_tracking and tb_overvoltage can be compared against a second, simple
implementation.  Plain Python 3, no third-party packages.  Parameter names
follow the generics of headlight_system (diode and IC internals as named in
diode.vhd and hbridge_ic.vhd).

Method: backward Euler on the reduced DAE (unknowns i, w, vs, out1, out2 per
step; rack position x follows from w), Newton with a finite-difference
Jacobian, step size 1e-7 s right after every discrete event growing to
2e-4 s.  The IC's 'above thresholds are located by bisection of the step, so
switching happens at the crossing as in VHDL-AMS; each switch is a restart
(the models' `break`).

Usage:  python3 headlight_check.py            (prints the figures of both runs)
"""

import math

# ---------------------------------------------------------------- parameters
P = dict(
    # dc_motor
    r=4.0, l=3.0e-3, kt=0.015, ke=0.015, d=1.5e-6, j=1.0e-6,
    # constant_friction: Tcst = tcst_motor + tcst_system, smoothed with tanh(w/w_s)
    tcst_motor=0.5e-3, tcst_system=2.0e-3, w_s=0.1,
    # gear_inertia, rack_pinion_gear, spring, reflector_mass, potentiometer
    jg=0.3e-6, gear_ratio=60.0, radius_p=1.2e-4, ks=5000.0, mass_extrapolated=0.3,
    k_pot=625.0, x0=0.0,
    # wiring_harness (per line)
    r_line=0.1, l_line=3.75e-6,
    # diode (battery reverse-polarity diode)
    is_bat=1.2e-12, n_bat=1.0, rs_bat=0.1,
    # hbridge_ic
    r_on_hs=2.2, r_on_ls=0.8, r_off=1.0e6,
    is_clamp_hs=2.6e-13, is_clamp_ls=1.2e-11, rs_clamp=0.25, n_clamp=1.0,
    r_q=1.5e3, c_vs=47.0e-6,
    deadband=0.1, hysteresis=0.05, ovhi_off=18.1, ovlo_off=17.5,
)
VT = 0.025865          # thermal voltage at 300.15 K
VJ_LIN = 1.2           # junction voltage above which the exponential is continued linearly


def pwl_battery(profile):
    """profile: v_init, [(t_start, duration, v_target), ...] -> (f(t), breakpoints)"""
    v_init, segs = profile
    pts = [(0.0, v_init)]
    v = v_init
    for t0, dur, vt in segs:
        pts.append((t0, v))
        pts.append((t0 + dur, vt))
        v = vt

    def f(t):
        val = pts[0][1]
        for (ta, va), (tb, vb) in zip(pts, pts[1:]):
            if t >= tb:
                val = vb
            elif t >= ta and tb > ta:
                return va + (vb - va) * (t - ta) / (tb - ta)
        return val

    bps = sorted({t for t, _ in pts if t > 0.0})
    return f, bps


def diode_i(v, i_s, n, rs):
    """Current of an exponential diode with series resistance at terminal voltage v."""
    nvt = n * VT

    def ij(vj):
        if vj > VJ_LIN:
            e = math.exp(VJ_LIN / nvt)
            return i_s * (e * (1.0 + (vj - VJ_LIN) / nvt) - 1.0)
        return i_s * (math.exp(vj / nvt) - 1.0)

    def dij(vj):
        return i_s * math.exp(min(vj, VJ_LIN) / nvt) / nvt

    lo, hi = min(v, 0.0), max(v, 0.0)
    vj = min(v, 0.6) if v > 0 else v
    for _ in range(60):
        g = ij(vj) - (v - vj) / rs
        if abs(g) < 1e-13:
            break
        if g > 0:
            hi = vj
        else:
            lo = vj
        step = g / (dij(vj) + 1.0 / rs)
        vn = vj - step
        if not (lo < vn < hi):
            vn = 0.5 * (lo + hi)
        if abs(vn - vj) < 1e-14:
            vj = vn
            break
        vj = vn
    return (v - vj) / rs


def solve_lin(a, b):
    n = len(b)
    m = [row[:] + [b[k]] for k, row in enumerate(a)]
    for c in range(n):
        p = max(range(c, n), key=lambda r_: abs(m[r_][c]))
        m[c], m[p] = m[p], m[c]
        for r_ in range(c + 1, n):
            f = m[r_][c] / m[c][c]
            for k in range(c, n + 1):
                m[r_][k] -= f * m[c][k]
    x = [0.0] * n
    for r_ in range(n - 1, -1, -1):
        x[r_] = (m[r_][n] - sum(m[r_][k] * x[k] for k in range(r_ + 1, n))) / m[r_][r_]
    return x


class Servo:
    def __init__(self, p, battery, vref_fn):
        self.p = p
        self.vbat, self.bps = battery
        self.vref = vref_fn
        self.rn = p["radius_p"] / p["gear_ratio"]
        self.jtot = p["j"] + p["jg"] + p["mass_extrapolated"] * self.rn ** 2
        self.ltot = p["l"] + 2 * p["l_line"]
        self.rtot = p["r"] + 2 * p["r_line"]
        self.tcst = p["tcst_motor"] + p["tcst_system"]

    # switch conductances from the logic state
    def sw(self, st):
        p = self.p
        up, down, ov = st
        on_hs1 = (not ov) and (not down)
        on_ls1 = (not ov) and down
        on_hs2 = (not ov) and (not up)
        on_ls2 = (not ov) and up
        g = lambda on, r_on: 1.0 / r_on if on else 1.0 / p["r_off"]
        return (g(on_hs1, p["r_on_hs"]), g(on_ls1, p["r_on_ls"]),
                g(on_hs2, p["r_on_hs"]), g(on_ls2, p["r_on_ls"]))

    def currents(self, z, vbat, st):
        p = self.p
        i, w, vs, o1, o2 = z
        ghs1, gls1, ghs2, gls2 = self.sw(st)
        c = dict(
            ihs1=(vs - o1) * ghs1, ils1=o1 * gls1,
            ihs2=(vs - o2) * ghs2, ils2=o2 * gls2,
            idh1=diode_i(o1 - vs, p["is_clamp_hs"], p["n_clamp"], p["rs_clamp"]),
            idl1=diode_i(-o1, p["is_clamp_ls"], p["n_clamp"], p["rs_clamp"]),
            idh2=diode_i(o2 - vs, p["is_clamp_hs"], p["n_clamp"], p["rs_clamp"]),
            idl2=diode_i(-o2, p["is_clamp_ls"], p["n_clamp"], p["rs_clamp"]),
            idb=diode_i(vbat - vs, p["is_bat"], p["n_bat"], p["rs_bat"]),
        )
        return c

    def resid(self, z, y0, dt, t, st):
        """Backward-Euler residual; dt=None gives the operating point with i=w=0 fixed."""
        p = self.p
        i, w, vs, o1, o2 = z
        i0, w0, vs0, o10, o20, x0 = y0
        vbat = self.vbat(t)
        c = self.currents(z, vbat, st)
        if dt is None:
            x = x0
            r0 = i - i0
            r1 = w - w0
            r2 = c["idb"] - vs / p["r_q"] - c["ihs1"] - c["ihs2"] + c["idh1"] + c["idh2"]
        else:
            x = x0 + dt * self.rn * w
            r0 = self.ltot * (i - i0) / dt - (o1 - o2 - self.rtot * i - p["ke"] * w)
            r1 = (self.jtot * (w - w0) / dt
                  - (p["kt"] * i - p["d"] * w - self.tcst * math.tanh(w / p["w_s"])
                     - self.rn * p["ks"] * x))
            r2 = (p["c_vs"] * (vs - vs0) / dt
                  - (c["idb"] - vs / p["r_q"] - c["ihs1"] - c["ihs2"] + c["idh1"] + c["idh2"]))
        r3 = c["ihs1"] - c["ils1"] - c["idh1"] + c["idl1"] - i
        r4 = c["ihs2"] - c["ils2"] - c["idh2"] + c["idl2"] + i
        return [r0, r1, r2, r3, r4]

    def newton(self, y0, dt, t, st):
        z = list(y0[:5])
        for _ in range(40):
            f = self.resid(z, y0, dt, t, st)
            jac = [[0.0] * 5 for _ in range(5)]
            for k in range(5):
                h = 1e-7 * max(1.0, abs(z[k]))
                zk = z[:]
                zk[k] += h
                fk = self.resid(zk, y0, dt, t, st)
                for r_ in range(5):
                    jac[r_][k] = (fk[r_] - f[r_]) / h
            dz = solve_lin(jac, [-v for v in f])
            # limit the node-voltage update (junction-limiting in spirit)
            lim = max(abs(dz[2]), abs(dz[3]), abs(dz[4])) / 2.0
            s = 1.0 / lim if lim > 1.0 else 1.0
            z = [a + s * b for a, b in zip(z, dz)]
            if max(abs(v) for v in dz) < 1e-10:
                break
        else:
            raise RuntimeError(f"Newton failed at t={t}")
        x = y0[5] + (0.0 if dt is None else dt * self.rn * z[1])
        return z + [x]

    # logic (the IC's processes driven by 'above events)
    def aboves(self, y, t):
        p = self.p
        e = self.vref(t) - p["k_pot"] * y[5]
        db, hy = p["deadband"], p["hysteresis"]
        return (e > db + hy, e > db, e > -db, e > -db - hy,
                y[2] > p["ovhi_off"], y[2] > p["ovlo_off"])

    @staticmethod
    def logic(st, a):
        up, down, ov = st
        a_up_on, a_up_off, a_dn_off, a_dn_on, a_ovhi, a_ovlo = a
        if a_up_on:
            up = True
        elif not a_up_off:
            up = False
        if not a_dn_on:
            down = True
        elif a_dn_off:
            down = False
        if a_ovhi:
            ov = True
        elif not a_ovlo:
            ov = False
        return (up, down, ov)

    def run(self, t_stop, ref_bps=(), dt_max=2e-4, dt_min=1e-7):
        p = self.p
        st = (False, False, False)
        y = self.newton([0.0, 0.0, max(self.vbat(0.0) - 0.6, 0.0), 0.0, 0.0, p["x0"]], None, 0.0, st)
        a = self.aboves(y, 0.0)
        st = self.logic(st, a)
        y = self.newton(y, None, 0.0, st)     # re-solve at t=0 after the initial break
        bps = sorted(set(self.bps) | set(ref_bps) | {t_stop})
        t, dt = 0.0, dt_min
        out = [(t, y, st)]
        events = []
        while t < t_stop - 1e-12:
            nb = min(b for b in bps if b > t + 1e-12)
            h = min(dt, nb - t)
            yn = self.newton(y, h, t + h, st)
            an = self.aboves(yn, t + h)
            if an != a:
                # locate the first crossing by bisection of the step
                lo, hi = 0.0, h
                for _ in range(40):
                    mid = 0.5 * (lo + hi)
                    ym = self.newton(y, mid, t + mid, st)
                    if self.aboves(ym, t + mid) != a:
                        hi = mid
                    else:
                        lo = mid
                    if hi - lo < 1e-9:
                        break
                h = hi
                yn = self.newton(y, h, t + h, st)
                an = self.aboves(yn, t + h)
                t += h
                new = self.logic(st, an)
                if new != st:
                    events.append((t, st, new))
                    st = new
                    yn = self.newton(yn, 1e-9, t + 1e-9, st)   # restart (break): states continuous
                    t += 1e-9
                y, a, dt = yn, an, dt_min
                out.append((t, y, st))
                continue
            t += h
            y, a = yn, an
            out.append((t, y, st))
            if abs(t - nb) < 1e-12 and nb in self.bps + list(ref_bps):
                dt = dt_min
            else:
                dt = min(dt * 1.5, dt_max)
        return out, events


def at(out, tq):
    best = min(out, key=lambda s: abs(s[0] - tq))
    return best


def vmotor(s, p):
    """conn1 - conn2 (motor terminals, after the harness): ke*w + (r)*i + L di/dt ~ o1-o2-2*r_line*i"""
    t, y, st = s
    i, w, vs, o1, o2, x = y
    return o1 - o2 - 2 * p["r_line"] * i  # harness L*di/dt negligible off switching instants


def report_tracking(p):
    vref0, t_step, dv = 1.0, 3.0, 1.0
    vref = lambda t: vref0 + (dv if t >= t_step else 0.0)
    s = Servo(p, pwl_battery((12.0, [])), vref)
    out, ev = s.run(6.0, ref_bps=(t_step,))
    db = p["deadband"]
    print("== tb_tracking (6 s): battery 12 V, vref 1.0 V -> 2.0 V at 3 s")
    for t, a, b in ev:
        print(f"   event t={t:.6f}s  (up,down,ov) {a} -> {b}")
    peak = max(abs(y[0]) for _, y, _ in out)
    print(f"   peak |i_motor|                  : {peak:.3f} A")
    for lbl, t_lo, t_hi, t_probe, vr in (("run 1", 0.0, 3.0, 2.9, vref0),
                                          ("run 2", 3.0, 6.0, 5.9, vref0 + dv)):
        seg = [o for o in out if t_lo <= o[0] < t_hi]
        t_db = next(o[0] for o in seg if vr - p["k_pot"] * o[1][5] < db)
        t_rest = next(o[0] for o in seg if o[0] > t_db and abs(o[1][1]) < 1.0)
        mid = at(out, t_lo + 0.5 * (t_db - t_lo) + 0.1)
        vm = vmotor(mid, p)
        run_i = mid[1][0]
        probe = at(out, t_probe)
        vfb = p["k_pot"] * probe[1][5]
        rest = [o for o in seg if o[0] > t_rest + 0.1]
        wmax = max(abs(o[1][1]) for o in rest)
        drift = p["k_pot"] * (rest[-1][1][5] - rest[0][1][5])
        nsw = sum(1 for te, _, _ in ev if t_rest < te < t_hi)
        print(f"   {lbl}: vfb enters deadband at    : {t_db:.3f} s (travel {vr - db:.2f} V"
              f" from {p['k_pot'] * seg[0][1][5]:.3f} V)")
        print(f"   {lbl}: shaft at rest (|w|<1) at  : {t_rest:.3f} s")
        print(f"   {lbl}: v_motor / i_motor tracking: {vm:.2f} V / {run_i:.3f} A at t={mid[0]:.2f} s"
              f" (v_supply {mid[1][2]:.2f} V, speed {mid[1][1] * 60 / (2 * math.pi):.0f} rpm,"
              f" travel rate {p['k_pot'] * s.rn * mid[1][1]:.3f} V/s)")
        print(f"   {lbl}: vfb at {t_probe} s             : {vfb:.4f} V; lower edge vref-deadband"
              f" = {vr - db:.4f} V; overshoot {vfb - (vr - db) * 1:.4f} V")
        print(f"   {lbl}: at {t_probe} s v_motor {vmotor(probe, p):.2e} V, i_motor {probe[1][0]:.2e} A,"
              f" v_conn = v_supply - {probe[1][2] - probe[1][3]:.2e} V")
        print(f"   {lbl}: at rest: max|w| {wmax:.2e} rad/s, vfb drift {drift:.2e} V,"
              f" switch events {nsw} (no chatter)")
    return out, ev


def report_overvoltage(p):
    prof = (0.0, [(0.0, 1.0, 12.0), (2.0, 1.0, 24.0), (3.0, 1.0, 12.0), (5.5, 1.5, 0.0)])
    bat = pwl_battery(prof)
    s = Servo(p, bat, lambda t: 4.8)
    out, ev = s.run(8.0)
    print("== tb_overvoltage (8 s): battery 0->12 V (0-1 s), 12->24 V (2-3 s), 24->12 V (3-4 s),"
          " 12->0 V (5.5-7 s); vref 4.8 V")
    for t, a, b in ev:
        print(f"   event t={t:.6f}s  (up,down,ov) {a} -> {b}")
    peak = max(abs(y[0]) for _, y, _ in out)
    print(f"   peak |i_motor|                  : {peak:.3f} A")
    s15 = at(out, 1.5)
    print(f"   at 1.5 s (12 V): v_bat - v_supply {bat[0](1.5) - s15[1][2]:.3f} V,"
          f" v_motor {vmotor(s15, p):.2f} V, i {s15[1][0]:.3f} A, v_conn1 {s15[1][3] - p['r_line'] * s15[1][0]:.2f} V")
    on = [e for e in ev if e[2][2] and not e[1][2]]
    off = [e for e in ev if e[1][2] and not e[2][2]]
    for t_on, _, _ in on:
        so = at(out, t_on)
        print(f"   OV engages at t={t_on:.4f} s: v_supply {so[1][2]:.3f} V (ovhi_off {p['ovhi_off']}),"
              f" v_bat {bat[0](t_on):.3f} V, speed {so[1][1] * 60 / (2 * math.pi):.0f} rpm")
        t_fw = next(o[0] for o in out if o[0] > t_on and abs(o[1][0]) < 1e-3)
        print(f"      freewheel current (|i| {abs(so[1][0]):.3f} A at switch-off) below 1 mA after"
              f" {(t_fw - t_on) * 1e6:.0f} us")
        for dtp in (20e-6, 0.2e-3, 5e-3, 50e-3):
            sp = at(out, t_on + dtp)
            print(f"      +{dtp * 1e3:6.2f} ms: i_motor {sp[1][0]:+.2e} A, v_motor {vmotor(sp, p):6.2f} V"
                  f" (back-EMF {p['ke'] * sp[1][1]:6.2f} V), v_conn1 {sp[1][3]:6.2f} V, v_conn2 {sp[1][4]:6.2f} V")
        coast = [o for o in out if o[0] > t_on and o[2][2]]
        t_stop = next((o[0] for o in coast if abs(o[1][1]) < 1.0), None)
        print(f"      motor coasts to rest at      : {t_stop if t_stop is None else round(t_stop, 3)} s")
        imax = max(abs(o[1][0]) for o in coast if o[0] > t_on + 5e-3)
        print(f"      max |i_motor| during OV after 5 ms: {imax:.2e} A")
    for t_off, _, _ in off:
        so = at(out, t_off)
        print(f"   OV releases at t={t_off:.4f} s: v_supply {so[1][2]:.3f} V (ovlo_off {p['ovlo_off']}),"
              f" v_bat {bat[0](t_off):.3f} V")
    for tp in (4.5, 6.0, 7.9):
        sp = at(out, tp)
        print(f"   at {tp} s: v_bat {bat[0](tp):5.2f} V, v_supply {sp[1][2]:5.2f} V, v_motor {vmotor(sp, p):6.2f} V,"
              f" i {sp[1][0]:+.3f} A, vfb {p['k_pot'] * sp[1][5]:.3f} V, state {sp[2]}")
    return out, ev


if __name__ == "__main__":
    report_tracking(P)
    report_overvoltage(P)
