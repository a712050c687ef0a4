"""Crankshaft beam: three-moment equation, springs, balance, hard cases."""

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from stackup.crank import BellakhdharLaw, reactions
from stackup.crank.beam import element_stiffness


def three_moment(spans, ei, positions, loads, settlement):
    """Reactions of a continuous beam on rigid supports by Clapeyron's three-moment equation.

    Independent reference: loads and settlements positive in the same
    direction; support moments sagging positive, zero at the free ends.
    M_{j-1} L_l/EI_l + 2 M_j (L_l/EI_l + L_r/EI_r) + M_{j+1} L_r/EI_r
        = -P_l a_l (L_l^2 - a_l^2)/(L_l EI_l) - P_r b_r (L_r^2 - b_r^2)/(L_r EI_r) + 6 (psi_l - psi_r)
    """
    n = len(spans)
    a = positions * spans
    b = spans - a
    psi = np.diff(settlement) / spans
    m = np.zeros(n + 1)
    if n > 1:
        mat = np.zeros((n - 1, n - 1))
        rhs = np.zeros(n - 1)
        for j in range(1, n):
            l, r = j - 1, j
            row = j - 1
            mat[row, row] = 2 * (spans[l] / ei[l] + spans[r] / ei[r])
            if row > 0:
                mat[row, row - 1] = spans[l] / ei[l]
            if row < n - 2:
                mat[row, row + 1] = spans[r] / ei[r]
            rhs[row] = (-loads[l] * a[l] * (spans[l] ** 2 - a[l] ** 2) / (spans[l] * ei[l])
                        - loads[r] * b[r] * (spans[r] ** 2 - b[r] ** 2) / (spans[r] * ei[r])
                        + 6 * (psi[l] - psi[r]))
        m[1:n] = np.linalg.solve(mat, rhs)
    reaction = np.zeros(n + 1)
    for i in range(n):
        left = (m[i + 1] - m[i] + loads[i] * b[i]) / spans[i]
        reaction[i] += left
        reaction[i + 1] += loads[i] - left
    return reaction


def test_two_equal_spans_textbook_values():
    # central point loads on two equal spans: 5P/16, 11P/8, 5P/16
    r = reactions(np.array([[1000.0, 0.0], [1000.0, 0.0]]), spans=[0.1, 0.1], EI=1e4, law=None)
    np.testing.assert_allclose(r.reactions[:, 0], [5000 / 16, 11000 / 8, 5000 / 16], rtol=1e-12)


def test_settled_central_support_loses_6EIdelta_over_L3():
    ei, span, delta = 1e4, 0.1, 10e-6
    offsets = np.array([[0.0, 0.0], [delta, 0.0], [0.0, 0.0]])
    r = reactions(np.zeros((2, 2)), spans=[span, span], EI=ei, offsets=offsets, law=None)
    assert r.reactions[1, 0] == pytest.approx(-6 * ei * delta / span**3, rel=1e-12)


@given(st.integers(1, 6), st.integers(0, 2**32 - 1))
def test_rigid_supports_give_the_three_moment_solution(n, seed):
    rng = np.random.default_rng(seed)
    spans = rng.uniform(0.05, 0.2, n)
    ei = rng.uniform(5e3, 2e4, (n, 2))
    positions = rng.uniform(0.1, 0.9, n)
    loads = rng.normal(0, 2e4, (n, 2))
    offsets = rng.normal(0, 20e-6, (n + 1, 2))
    r = reactions(loads, spans=spans, EI=ei, load_positions=positions, offsets=offsets, law=None)
    for c in range(2):
        want = three_moment(spans, ei[:, c], positions, loads[:, c], offsets[:, c])
        np.testing.assert_allclose(r.reactions[:, c], want, rtol=1e-9, atol=1e-9 * np.abs(loads).sum())


def full_beam_with_springs(spans, ei, positions, loads, offsets, k):
    """Direct linear solve of the uncondensed beam on springs (one plane)."""
    n = len(spans)
    nodes = 2 * n + 1
    mat = np.zeros((2 * nodes, 2 * nodes))
    rhs = np.zeros(2 * nodes)
    for i in range(n):
        a = positions[i] * spans[i]
        for j, length in enumerate((a, spans[i] - a)):
            first = 2 * i + j
            dofs = [2 * first, 2 * first + 1, 2 * first + 2, 2 * first + 3]
            mat[np.ix_(dofs, dofs)] += element_stiffness(length, ei[i])
        rhs[2 * (2 * i + 1)] += loads[i]
    for j in range(n + 1):
        mat[4 * j, 4 * j] += k[j]
        rhs[4 * j] += k[j] * offsets[j]
    w = np.linalg.solve(mat, rhs)[0::4]
    return k * (w - offsets)


@given(st.integers(1, 5), st.integers(0, 2**32 - 1))
def test_linear_springs_agree_with_a_direct_solve(n, seed):
    rng = np.random.default_rng(seed)
    spans = rng.uniform(0.05, 0.2, n)
    ei = rng.uniform(5e3, 2e4, n)
    positions = rng.uniform(0.1, 0.9, n)
    loads = rng.normal(0, 2e4, (n, 2))
    offsets = rng.normal(0, 20e-6, (n + 1, 2))
    k = rng.uniform(0.5e9, 2e9, n + 1)
    r = reactions(loads, spans=spans, EI=ei, load_positions=positions, offsets=offsets, law=k)
    for c in range(2):
        np.testing.assert_allclose(r.reactions[:, c], full_beam_with_springs(spans, ei, positions, loads[:, c],
                                                                            offsets[:, c], k), rtol=1e-9, atol=1e-6)


SPANS = np.full(4, 0.085)
EI = 210e9 * np.array([[49468, 53971], [55768, 53634], [55768, 53634], [49468, 53971]]) * 1e-12


def balance(r, loads, positions=None):
    """Force and moment residuals relative to the load scale."""
    z_support = np.concatenate([[0], np.cumsum(SPANS)])
    pos = 0.5 if positions is None else positions
    z_load = z_support[:-1] + pos * SPANS
    scale = np.abs(loads).sum(axis=(-2, -1))[..., None] + 1.0
    force = np.abs(r.reactions.sum(-2) - loads.sum(-2)) / scale
    moment = np.abs(np.einsum("p,...pc->...c", z_support, r.reactions) - np.einsum("p,...pc->...c", z_load, loads))
    return force.max(), (moment / (scale * z_support[-1])).max()


@pytest.mark.parametrize("law", [None, 1.2e9, BellakhdharLaw(), BellakhdharLaw(dx=0.0), BellakhdharLaw(clearance=0.0)])
@given(seed=st.integers(0, 2**32 - 1))
def test_reactions_balance_loads_in_force_and_moment(law, seed):
    rng = np.random.default_rng(seed)
    loads = rng.normal(0, 2e4, (30, 4, 2)).cumsum(axis=0) / 5
    offsets = rng.normal(0, 15e-6, (5, 2))
    r = reactions(loads, spans=SPANS, EI=EI, offsets=offsets, law=law)
    assert r.converged.all()
    f, m = balance(r, loads)
    assert f < 1e-9 and m < 1e-9


def cycle_loads(peak, n=720):
    angle = np.radians(np.arange(n) * 720 / n)
    loads = np.zeros((n, 4, 2))
    for i, phase in enumerate(np.radians([0, 540, 180, 360])):
        a = np.mod(angle - phase + np.pi, 4 * np.pi) - np.pi
        loads[:, i, 0] = peak * np.exp(-(a / 0.4) ** 2) - 0.05 * peak * np.cos(angle)
        loads[:, i, 1] = 0.1 * peak * np.sin(angle + phase)
    return loads


@pytest.mark.parametrize(
    "name, kw",
    [
        ("zero load", dict(loads=np.zeros((50, 4, 2)))),
        ("zero load, misaligned", dict(loads=np.zeros((5, 4, 2)), offsets=np.array([[0, 0], [30e-6, 0], [-20e-6, 5e-6], [0, 0], [10e-6, 0]]))),
        ("1e6 N loads", dict(loads=cycle_loads(1e6))),
        ("clearance to zero", dict(loads=cycle_loads(4e4), law=BellakhdharLaw(clearance=0.0))),
        ("dx to zero (bilinear)", dict(loads=cycle_loads(4e4), law=BellakhdharLaw(dx=0.0))),
        ("tiny dx", dict(loads=cycle_loads(4e4), law=BellakhdharLaw(dx=1e-12))),
        ("offsets beyond the clearance", dict(loads=cycle_loads(4e4), offsets=np.array([[0, 0], [80e-6, 0], [-60e-6, 40e-6], [90e-6, 0], [0, 0]]))),
        ("loads reversing through zero", dict(loads=np.linspace(-1, 1, 201)[:, None, None] * np.array([[3e4, 1e3], [-2e4, 0], [1e4, -5e2], [0, 2e3]]))),
    ],
)
def test_hard_cases_converge(name, kw):
    law = kw.pop("law", BellakhdharLaw())
    loads = kw.pop("loads")
    r = reactions(loads, spans=SPANS, EI=EI, law=law, **kw)
    assert r.converged.all(), name
    assert np.all(np.isfinite(r.reactions))
    f, m = balance(r, loads)
    assert f < 1e-9 and m < 1e-9, name


def test_nonconvergence_is_marked_not_hidden(monkeypatch):
    import stackup.crank.shaft as shaft

    monkeypatch.setattr(shaft, "MAX_ITERATIONS", 1)
    r = shaft.reactions(cycle_loads(4e4)[:3] * 0 + 4e4, spans=SPANS, EI=EI, law=BellakhdharLaw())
    assert not r.converged.all()
    assert set(np.unique(r.status)) <= {0, 1}
    assert shaft.STATUS[1] == "max_iterations"


def test_law_parameters_per_bearing_and_per_engine():
    loads = np.broadcast_to(cycle_loads(4e4, 36), (3, 36, 4, 2))
    clearance = np.array([[30e-6] * 5, [37e-6] * 5, [60e-6] * 5])[:, None, :]
    r = reactions(loads, spans=SPANS, EI=EI, law=BellakhdharLaw(clearance=clearance))
    peak = np.linalg.norm(r.reactions, axis=-1).max(axis=(1, 2))
    assert r.converged.all() and peak.shape == (3,)
    with pytest.raises(ValueError, match="constant along the sequence"):
        reactions(loads, spans=SPANS, EI=EI, law=BellakhdharLaw(clearance=np.full((3, 36, 5), 37e-6)))


def test_stiffer_supports_approach_rigid():
    loads = cycle_loads(4e4, 72)
    rigid = reactions(loads, spans=SPANS, EI=EI)
    stiff = reactions(loads, spans=SPANS, EI=EI, law=1e13)
    np.testing.assert_allclose(stiff.reactions, rigid.reactions, atol=5.0)


@pytest.mark.parametrize(
    "kw, message",
    [
        (dict(spans=[0.085, -0.085, 0.085, 0.085]), r"spans: -0.085 is not valid; must be > 0"),
        (dict(EI=np.ones(3)), r"EI: shape \(3,\) is not valid"),
        (dict(load_positions=[0.5, 1.0, 0.5, 0.5]), r"load_positions: 1.0 is outside the valid range \(0.0, 1.0\)"),
        (dict(offsets=np.zeros((4, 2))), r"offsets: shape \(4, 2\) is not valid; expected \(..., 5, 2\)"),
        (dict(pin_loads=np.full((4, 2), np.nan)), r"pin_loads: nan is not a finite number"),
        (dict(law=-1.0), r"law: -1.0 is not valid; must be > 0"),
    ],
)
def test_bad_input(kw, message):
    args = dict(pin_loads=np.zeros((4, 2)), spans=SPANS, EI=EI)
    args.update(kw)
    with pytest.raises(ValueError, match=message):
        reactions(args.pop("pin_loads"), **args)
