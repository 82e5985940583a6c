"""The worked example examples/python/aeb_in_the_loop.py: a Python AEB function drives Ego
through the bundled cut-in (run to 20 s). Under its default controller Ego runs into the
OverTaker; with the AEB it does not, and the minimum TTC stays above the bound worked out in
the example's doc (1.9 s)."""

from __future__ import annotations

import importlib.util
from conftest import REPO

spec = importlib.util.spec_from_file_location("aeb_in_the_loop", REPO / "examples" / "python" / "aeb_in_the_loop.py")
assert spec is not None and spec.loader is not None
aeb_in_the_loop = importlib.util.module_from_spec(spec)
spec.loader.exec_module(aeb_in_the_loop)


def test_default_controller_collides_aeb_avoids():
    collided, _, sim = aeb_in_the_loop.run(None)
    assert collided
    aeb = aeb_in_the_loop.Aeb()
    collided, min_ttc, sim = aeb_in_the_loop.run(aeb)
    assert not collided
    assert sim.stop_reason == "stop_trigger" and sim.time == 20.0
    # The AEB engaged (TTC went below its 2 s threshold) and kept TTC above the worked bound.
    assert min_ttc is not None and aeb_in_the_loop.MIN_TTC_BOUND < min_ttc < 2.0
    # Braked to the OverTaker's 15 m/s (or just below, by one step of 8 m/s² · 0.05 s).
    assert 15.0 - 0.4 - 1e-6 <= sim.entity("Ego").speed <= 15.0
