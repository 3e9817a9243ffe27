#!/usr/bin/python3
"""The restitution each peer's damping mapping actually gives a head-on Hertz collision.

    restitution_check.py

Both LIGGGHTS (model hertz) and Yade (Law2_ScGeom_MindlinPhys_Mindlin with en) add a normal
viscous force c v_n with c = 2 b sqrt(m* S_n), S_n = 2 E* sqrt(R* delta) the tangent Hertz stiffness
(Tsuji et al. 1992 scaling, so the restitution does not depend on the impact speed). They differ in
b and in the end of contact:
  LIGGGHTS 3.8: b = sqrt(5/6) |ln e| / sqrt(ln^2 e + pi^2); the total normal force may turn
                attractive near separation (no limitForce by default);
  Yade 2023.02a: b = Thornton et al. (2013) eqs. (B6)-(B7), a fit of the exact relation; the
                total normal force is kept >= 0.
This integrates m* delta'' = -kno delta^1.5 - c delta' for one unit collision (dimensionless:
m* = kno = 1, v0 = 1; e does not depend on them) with a fine step and prints the achieved
restitution for the README's pairs. Formulas as published; no code from either program.
"""
import math


def beta_liggghts(e):
    log_e = math.log(e)
    return math.sqrt(5.0 / 6.0) * -log_e / math.sqrt(log_e * log_e + math.pi * math.pi)


def beta_yade(e):
    h = [-6.918798, -16.41105, 146.8049, -796.4559, 2928.711, -7206.864, 11494.29, -11342.18, 6276.757,
         -1489.915]  # Thornton et al. (2013), Table 2
    poly = 0.0
    for coefficient in reversed(h):
        poly = poly * e + coefficient
    alpha = e * poly  # eq. (B7)
    return math.sqrt(1.0 / (1.0 - (1.0 + e) ** 2 * math.exp(alpha)) - 1.0)  # eq. (B6)


def achieved_restitution(b, clamp):
    # delta'' = -delta^1.5 - 2 b sqrt(1.5 delta^0.5) delta'  (m* = kno = 1, S_n = 1.5 kno delta^0.5)
    delta, rate, dt = 0.0, 1.0, 1e-5
    while True:
        force = -delta**1.5 - 2.0 * b * math.sqrt(1.5 * math.sqrt(max(delta, 0.0))) * rate
        if clamp:
            force = min(force, 0.0)  # no attraction: the wall or particle only pushes
        rate += force * dt
        delta += rate * dt
        if delta <= 0.0:
            return -rate


def main():
    print("pair          e target  LIGGGHTS b  e achieved   Yade b  e achieved")
    for name, e in (("M1-M1", 0.5), ("M1-steel", 0.4), ("M2-M2", 0.4), ("steel-steel", 0.6)):
        bl, by = beta_liggghts(e), beta_yade(e)
        print(f"{name:12s}  {e:8.2f}  {bl:10.4f}  {achieved_restitution(bl, False):10.4f}   "
              f"{by:6.4f}  {achieved_restitution(by, True):10.4f}")


if __name__ == "__main__":
    main()
