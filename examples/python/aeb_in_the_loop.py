"""AEB in the loop: a small automatic emergency braking function, written in Python, drives
Ego through the bundled cut-in (examples/scenarios/cut_in_highway.xosc).

The scenario: Ego keeps 25 m/s in lane −2; the OverTaker passes at 32 m/s, cuts into Ego's
lane once it is 10 m ahead (CutInEvent, t ≈ 5.65 s, lane change over 2 s), and 0.5 s after the
cut-in brakes at 4 m/s² to 15 m/s (BrakeEvent, t ≈ 8.15 s). The scenario stops at $EndTime,
10 s by default, before anything happens to Ego; here it runs to 20 s (EndTime = 20), and Ego,
under its default controller, keeps 25 m/s and runs into the OverTaker at t ≈ 14.5 s.

The AEB function reads the §8.7 time_to_collision (bounding boxes, both keeping their
velocities) each step and brakes Ego at `deceleration` while it is below `ttc_brake`, until
Ego is no faster than the car ahead; then it holds Ego's speed.

Worked threshold (gaps between the bounding boxes, as time_to_collision measures them):
- After the cut-in (t ≈ 7.65 s) the gap is ≈ 10 + 7·2 = 24 m, growing at 32 − 25 = 7 m/s;
  0.5 s later the OverTaker brakes. τ s into its braking the closing speed is 4τ − 7, and the
  gap 27.5 + 7τ − 2τ² (max 33.6 m at τ = 1.75 s). It reaches 15 m/s at τ = 4.25 s with a gap
  of 21.1 m, closing at 10 m/s: TTC = 2.11 s. Before that, TTC = (33.6 − 2u²)/(4u), u = τ − 1.75,
  stays above 2 s (it is 2.11 s at u = 2.5).
- So TTC first drops below ttc_brake = 2 s just after, with the OverTaker at a steady 15 m/s:
  gap 20 m, closing 10 m/s. Braking at 8 m/s² ends the closing after 10/8 = 1.25 s and
  10²/(2·8) = 6.25 m: the gap never drops below 20 − 6.25 = 13.75 m, and TTC = gap / closing
  speed only grows while Ego brakes (d/dt of (20 − 10t + 4t²)/(10 − 8t) is 60/100 > 0 at t = 0).
- The decision uses the state at the start of a step and the brake acts during the step, so
  TTC can fall one step (0.05 s) below the moment it was seen under 2 s, which itself is at most
  one step after the crossing: the minimum TTC stays above 2 − 2·0.05 = 1.9 s
  (MIN_TTC_BOUND), with no collision.

Run: python examples/python/aeb_in_the_loop.py (after pip install ./crates/python).
"""

from __future__ import annotations

from pathlib import Path
from typing import Optional, Tuple

import oscsim

ROOT = Path(__file__).resolve().parents[2]
BUNDLED = ROOT / "examples" / "scenarios" / "cut_in_highway.xosc"
# The worked bound of the module doc.
MIN_TTC_BOUND = 1.9


class Aeb:
    """Brakes at `deceleration` (m/s²) while the time to collision with `target` is below
    `ttc_brake` (s), until Ego is no faster than `target`; then holds Ego's speed."""

    def __init__(self, target: str = "OverTaker", ttc_brake: float = 2.0, deceleration: float = 8.0):
        self.target = target
        self.ttc_brake = ttc_brake
        self.deceleration = deceleration
        self.braking = False
        self.min_ttc: Optional[float] = None

    def step(self, sim: oscsim.Simulation, ego: oscsim.Entity) -> Optional[oscsim.Acceleration]:
        other = sim.entity(self.target)
        ttc = ego.time_to_collision(other)
        if ttc is not None:
            self.min_ttc = ttc if self.min_ttc is None else min(self.min_ttc, ttc)
        if self.braking:
            if ego.speed <= other.speed:
                self.braking = False
                return oscsim.Acceleration(0.0)
            return oscsim.Acceleration(-self.deceleration)
        if ttc is not None and ttc < self.ttc_brake:
            self.braking = True
            return oscsim.Acceleration(-self.deceleration)
        return None


def run(aeb: Optional[Aeb], end_time: float = 20.0) -> Tuple[bool, Optional[float], oscsim.Simulation]:
    """Runs the bundled cut-in to `end_time` with `aeb` driving Ego (None: the default
    controller); returns whether Ego's and the OverTaker's boxes ever overlapped, the minimum
    TTC seen and the simulation."""
    sim = oscsim.Simulation(BUNDLED, params={"EndTime": end_time})
    if aeb is not None:
        sim.set_controller("Ego", aeb)
    collided, min_ttc = False, None
    while sim.step() is None:
        ttc = sim.entity("Ego").time_to_collision(sim.entity("OverTaker"))
        if ttc is not None:
            collided = collided or ttc == 0.0
            min_ttc = ttc if min_ttc is None else min(min_ttc, ttc)
    return collided, min_ttc, sim


def main() -> None:
    collided, _, sim = run(None)
    print(f"default controller: collision {collided} (run ends at {sim.time:.2f} s)")
    collided, min_ttc, sim = run(Aeb())
    ego = sim.entity("Ego")
    print(
        f"AEB: collision {collided}, minimum TTC {min_ttc:.3f} s (bound {MIN_TTC_BOUND} s), "
        f"Ego at {ego.speed:.2f} m/s at {sim.time:.2f} s"
    )


if __name__ == "__main__":
    main()
