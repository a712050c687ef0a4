"""Selective assembly: intermediate pairs stand in before a bearing is a stock-out."""

from dataclasses import replace

import numpy as np

from stackup import schemes
from stackup._random import lot_generator, seed_sequence
from stackup.assembly import ASSEMBLED, SHELL_STOCKOUT, assemble, shell_demand
from stackup.engines import load_engine
from stackup.parts import draw_lot


def _lot(scheme, supply, seed=0, engines=2000):
    engine = load_engine("iso-example")
    engine = replace(engine, shell_wall=replace(engine.shell_wall, **supply))
    parts, normals = draw_lot(engine, lot_generator(seed_sequence(seed), 0), engines)
    share = None
    if engine.shell_wall.mode == "to-order":
        share = engine.shell_wall.aim_share(scheme, shell_demand(scheme, parts))
    return parts, [engine.shell_wall.make(scheme, normals, share)], engines


def test_scheme6_intermediate_pairs_lower_the_stock_outs_on_the_same_parts():
    # shells sorted from one process (grade quantities follow the process, not the demand): bins run
    # short, and A+C, A+D, B+D then fit bearings that would otherwise be stock-outs
    with_pairs = schemes.load("iso13778-6")
    without = replace(with_pairs, alternatives={})
    parts, shells, n = _lot(with_pairs, {"mode": "sorted", "process": {"distribution": "normal", "cpk": 1.0},
                                         "surplus": 0.05})
    a = assemble(with_pairs, parts, shells, lot_engines=n)
    b = assemble(without, parts, shells, lot_engines=n)
    out_a, out_b = np.count_nonzero(a.status == SHELL_STOCKOUT), np.count_nonzero(b.status == SHELL_STOCKOUT)
    assert out_b > 0 and out_a < out_b
    # every bearing the pairs saved is assembled within the scheme's clearance range (true sizes may
    # sit outside their read grade by the gauge error: 1 um of slack per part)
    saved = (a.status == ASSEMBLED) & (a.option > 0)
    assert saved.any()
    lo, hi = with_pairs.clearance_limits()
    assert np.all((a.clearance[saved] > lo - 4e-6) & (a.clearance[saved] < hi + 4e-6))


def test_shells_made_to_order_rarely_need_the_pairs():
    scheme = schemes.load("iso13778-6")
    parts, shells, n = _lot(scheme, {})
    a = assemble(scheme, parts, shells, lot_engines=n)
    assert np.count_nonzero(a.option > 0) <= np.count_nonzero(a.status == ASSEMBLED) // 10
