r"""The crankshaft's supports in the block: linear and angular compliance of each main bearing's bulkhead and cap.

One description of the housing serves both stages that meet it: the
crankshaft on its bearing law moves the journal through the support's linear
compliance (Bellakhdhar et al.'s deformation stiffness, :attr:`Supports.law_stiffness`),
and the support moments over the cycle (:mod:`stackup.film.coupled`) turn the bore
through its angular compliance, in series with the film's (Rozhdestvensky et al.
2018, eq. 5: :math:`K_s^\lambda`, :math:`K_s^\varphi` per plane).

Where no finite-element or measured compliance is at hand,
:func:`bulkhead_compliance` derives the angular one from the bulkhead's web
as a plate strip (its assumptions there). The bore's own surface turns too:
the deformation stiffness that moves the journal's centre in the bearing law
comes from a plane-strain model of a slice of the bearing, so a load that
varies across the width deforms each slice by its share
(:func:`ring_tilt_compliance`, in series with the web's).

References
----------
.. [1] Rozhdestvensky, Y. et al., Tribology in Industry 40 (2018), sec. 2.3, eq. 5 (linear and angular
   compliances of the supports, both planes).
.. [2] Bellakhdhar, B., Dogui, A., Ligier, J.-L., C. R. Mecanique 341 (2013) 743-754 (the bearing's
   deformation stiffness k_lv, k_hv).
.. [3] Timoshenko, S., Woinowsky-Krieger, S., *Theory of Plates and Shells*, 2nd ed., McGraw-Hill, 1959,
   sec. 1-2 (cylindrical bending of a plate strip: :math:`D = Et^3/(12(1-\nu^2))` per unit width).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from .._validate import POISSON, Finite, OrNone, Positive, validated


@dataclass(frozen=True)
class Supports:
    """Compliance of the main bearings' supports in the block, and their offset by its thermal deformation [SI].

    Attributes
    ----------
    linear : numpy.ndarray (N+1, 2)
        Linear compliance of each support [m/N]: load towards the cap, load towards the block (the bearing
        law's deformation stiffness is its inverse, :attr:`law_stiffness`; between the two the law's sigmoid
        in the load's direction, so the transverse plane's is the law's at 90 deg).
    angular : numpy.ndarray (N+1, 2)
        Angular compliance of each support [rad/(N m)], per component of the slope: in the plane of the
        cylinders (component 0, the load towards the caps) and across it (component 1).
    thermal_offset : numpy.ndarray (N+1, 2) or None
        Bore centres off the line by the block's thermal deformation [m] (Rozhdestvensky et al.'s Table 3,
        type 1), on top of the sampled coaxiality.
    source : str
        Where the compliances come from.
    thermal_source : str
    angular_derived : bool
        The angular compliance is :func:`bulkhead_compliance`'s, from a web the engine file describes (its
        stated error, a factor of two either way, a declared model uncertainty), not given as a number.
    ring : numpy.ndarray (N+1, 2) or None
        Angular compliance of the bore's surface against its ring [rad/(N m)], per component of the slope as
        ``angular``: the deformation under the linear compliance taken slice by slice across the width
        (:func:`ring_tilt_compliance`); None where not derived (the ring rigid).
    """

    linear: np.ndarray
    angular: np.ndarray
    thermal_offset: np.ndarray | None = None
    source: str = ""
    thermal_source: str = ""
    angular_derived: bool = False
    ring: np.ndarray | None = None

    @property
    def law_stiffness(self):
        """The bearing law's deformation stiffness per bearing [N/m]: ``{"k_lv": (N+1,), "k_hv": (N+1,)}``."""
        return {"k_lv": 1.0 / self.linear[:, 0], "k_hv": 1.0 / self.linear[:, 1]}

    @property
    def tilt_compliance(self):
        """The bore's turn per moment of the film [rad/(N m)] (N+1, 2): the bulkhead's (``angular``) in series
        with the ring's own (``ring``)."""
        return self.angular if self.ring is None else self.angular + self.ring

    def scaled(self, factor):
        """These supports with the angular compliance, the bulkhead's and the ring's, times ``factor``."""
        return replace(self, angular=self.angular * factor, ring=None if self.ring is None else self.ring * factor)

    @property
    def rigid(self):
        """The block is rigid against tilt (every angular compliance 0)."""
        return not np.any(self.tilt_compliance)


@validated(stiffness=Positive(), bearing_width=Positive())
def ring_tilt_compliance(*, stiffness, bearing_width):
    r"""Angular compliance of a bore's surface from the bearing's deformation stiffness across its width [rad/(N m)].

    Parameters
    ----------
    stiffness : array_like (..., 2)
        The bearing's deformation stiffness :math:`K_d` [N/m] for a load in each plane of the slope's
        components: in the cylinders' plane (0), the load towards the cap (the law's :math:`k_{lv}`); across it
        (1), the law's at 90 deg.
    bearing_width : float
        :math:`B` [m].

    Returns
    -------
    numpy.ndarray (..., 2)
        :math:`12 / (K_d B^2)`.

    Notes
    -----
    Bellakhdhar et al. identify :math:`K_d` on a plane-strain finite-element
    model of a slice of the bearing (liners, cap, the housing's half and the
    journal, 22 mm thick): every slice :math:`dz` of the width deforms under its
    own load, stiffness :math:`K_d\,dz/B`, as a Winkler foundation along the
    journal. A film moment :math:`M` across the width, carried as a load
    :math:`q(z) = 12 M z / B^3` on :math:`-B/2 \le z \le B/2`, then turns the
    bore's surface by

    .. math:: \varphi = \frac{q(z)\,B/K_d}{z} = \frac{12\,M}{K_d\,B^2},

    in series with the bulkhead's turn of the ring as a body
    (:func:`bulkhead_compliance`). The same load moves the journal's centre by
    :math:`F/K_d` in the bearing law, so one stiffness describes the housing in
    both stages.

    Assumptions: the slices do not hold each other (plane strain), so this is
    the upper end of the ring's compliance: in three dimensions the cap and
    ring carry part of the moment in torsion and out-of-plane bending. For a
    cap of square section (side :math:`B`, span :math:`L` between its bolts,
    both ends held) whose bending gives :math:`K_d`
    (:math:`F L^3/(192 E I)`), the couple twisting it instead
    (:math:`\varphi = TL/(4GK)`, :math:`K = 0.141 B^4`) turns it by
    :math:`2.4 (E/G) (B/L)^2` of the slices' turn: about a quarter at
    :math:`L = 5B`. The declared uncertainty on the supports' angular
    compliance, a factor of two either way
    (:func:`stackup.scenarios.support_tilt_compliance`), takes this term with
    the web's.

    References
    ----------
    .. [1] Bellakhdhar, B., Dogui, A., Ligier, J.-L., C. R. Mecanique 341 (2013) 743-754, sec. 4.1 (plane
       strain, CPE4R elements, 22 mm thick).
    .. [2] Young, W. C., Budynas, R. G., Sadegh, A. M., Roark's Formulas for Stress and Strain, 8th ed., 2012,
       Table 8.1 case 1d (a beam held at both ends, load at mid-span), Table 10.7 case 4 (torsion of a square
       section).
    """
    return 12.0 / (np.asarray(stiffness, dtype=float) * float(bearing_width) ** 2)


@validated(thickness=Positive(), height=Positive(), width=Positive(), ring_height=Positive(), modulus=Positive(),
           poisson=POISSON)
def bulkhead_compliance(*, thickness, height, width, ring_height, modulus, poisson):
    r"""Angular compliance of a main bearing's support from its bulkhead web as plate strips [rad/(N m)].

    Parameters
    ----------
    thickness : array_like (N+1,)
        Thickness of each bulkhead's web along the crankshaft [m].
    height : float or array_like (N+1,)
        From the bore centre up to where the cylinder barrels and deck stiffen the web [m].
    width : float or array_like (N+1,)
        Between the crankcase's side walls (skirts) at the bore's height [m].
    ring_height : float or array_like (N+1,)
        Depth of the web strip across the block that carries the transverse turn: the housing ring's
        outer diameter [m].
    modulus, poisson : float
        Of the block's material [Pa], [-].

    Returns
    -------
    numpy.ndarray (N+1, 2)
        Per component of the slope: in the cylinders' plane (0) and across it (1).

    Notes
    -----
    A moment :math:`M` at the bore turns the bore ring (and its cap, bolted to
    it) as a rigid body; the web around it bends out of its plane as plate
    strips in cylindrical bending, flexural rigidity
    :math:`D = E t^3 / (12(1-\nu^2))` per unit width:

    - in the cylinders' plane (a turn about the transverse axis) the web from
      the ring up to the barrels, height :math:`H`, width :math:`W`, a strip
      clamped at the top under an end moment:
      :math:`\varphi/M = H / (D W)`;
    - across it (a turn about the vertical axis) the web across the block, depth
      :math:`d` (the ring's), clamped at both side walls, span :math:`W`, under a
      couple at mid-span: :math:`\varphi/M = W / (16 D d)`.

    Assumptions: the web is a flat plate of uniform thickness (ribs, the oil
    gallery and the bolt bosses are left out), clamped where it meets the
    barrels and the skirts (their own compliance is left out, so the model
    is stiff there), the ring and cap are rigid, and the two turns do not
    interact. Its error against a finite-element model of a bulkhead is not
    measured here (Rozhdestvensky et al.'s FE compliances, their Figs. 5-6, are
    drawn, not tabulated); the clamps and the missing ribs err in opposite
    directions, and a factor of two either way is the uncertainty a study
    declares with it (``studies/coupled_supports.py`` runs the compliance at 0,
    0.5, 1 and 2 times).

    References
    ----------
    .. [1] Timoshenko, S., Woinowsky-Krieger, S., *Theory of Plates and Shells*, 2nd ed., 1959, sec. 1-2.
    .. [2] Roark's Formulas for Stress and Strain, 8th ed., 2012, Table 8.1 (cases 3e and 4e: a beam
       clamped at one end under an end couple, at both ends under a couple at mid-span).
    """
    t = np.asarray(thickness, dtype=float)
    h, w, d = (np.broadcast_to(np.asarray(a, dtype=float), t.shape) for a in (height, width, ring_height))
    rigidity = modulus * t**3 / (12.0 * (1.0 - poisson**2))
    vertical = h / (rigidity * w)
    transverse = w / (16.0 * rigidity * d)
    return np.stack([vertical, transverse], axis=-1)


@validated(linear=Positive(), angular=Positive(zero=True), thermal_offset=OrNone(Finite()),
           ring=OrNone(Positive(zero=True)))
def supports(*, linear, angular, thermal_offset=None, source="", thermal_source="", ring=None):
    """A :class:`Supports` from compliances per bearing (N+1, 2) or one row for all, checked.

    ``linear`` [m/N] > 0 (a rigid support is a very small compliance), ``angular`` [rad/(N m)] >= 0 (0: the
    block rigid against tilt), ``thermal_offset`` [m] (N+1, 2) or None, ``ring`` [rad/(N m)] >= 0 (the bore's
    own turn, :func:`ring_tilt_compliance`) or None.
    """
    rows = {name: np.atleast_2d(np.asarray(value, dtype=float))
            for name, value in (("linear", linear), ("angular", angular), ("ring", ring)) if value is not None}
    n = max(*(value.shape[0] for value in rows.values()), 0 if thermal_offset is None else np.shape(thermal_offset)[0])
    for name, value in rows.items():
        if value.shape[-1] != 2 or value.shape[0] not in (1, n):
            raise ValueError(f"{name}: shape {value.shape} is not valid; give (bearings, 2) or (1, 2)")
    offset = None if thermal_offset is None else np.asarray(thermal_offset, dtype=float)
    if offset is not None and offset.shape != (n, 2):
        raise ValueError(f"thermal_offset: shape {offset.shape} is not valid; give ({n}, 2)")
    full = {name: np.broadcast_to(value, (n, 2)).copy() for name, value in rows.items()}
    return Supports(full["linear"], full["angular"], offset, source, thermal_source, ring=full.get("ring"))
