r"""Scheme designer: grade limits, shell grades and pairing that suit one engine.

ISO 13778's schemes are generic; :func:`scheme` designs one for a given
engine's processes, gauges, press fit and operating-clearance window
(:func:`design` gives it with what the designer found;
:mod:`~stackup.design.designer`).

Decision variables

- housing and journal grade limits, on the read-out grid (``readout``, or the
  gauge's resolution if coarser), each grade at least as wide as the gauge can
  sort (a part at the grade's centre is read into it with probability at
  least ``sort_share``);
- shell grade limits, contiguous, hence the aims of shells made to order
  (the grade centres); each grade at least as wide as the shell process and
  its gauge can sort (a shell aimed at the grade's centre is read into it
  with probability at least ``sort_share``);
- the pairing table: one shell pair per cell, a grade with itself or (with
  ``mixed_pairs``) with the next grade, the intermediate pairs of ISO 13778.

Objective (all on one fixed design sample, common random numbers)

.. math:: J = P_{out} + \lambda \max_s P^s_{out} + w_s\,\text{surplus} + w_o\,\text{shortfall}

:math:`P_{out}`: share of the bearings whose operating clearance (press fit,
housing swell and temperature by :func:`stackup.fit.press_fit` with the
engine's press-fit data) lies outside the window; :math:`P^s_{out}` the same
under each declared scenario that changes the clearance
(:data:`stackup.scenarios.DECLARED`: process mean shifts of one sigma, gauge
repeatability 2 um; the misalignment scenario changes loads and films, not
the clearance); surplus and shortfall: shells per bearing of the planned
shell supply left over and missing (:mod:`stackup.design.pairing`).

Solvers: housing and journal limits by differential evolution
(``scipy.optimize.differential_evolution``) on the read-out grid, polished
limit by limit; shell limits by bounded Nelder-Mead from the best of a few
starts (equal widths; the start scheme's grades); the pairing by a
mixed-integer programme (HiGHS through ``scipy.optimize.milp``). The shells
are integrated out on the sample (:mod:`stackup.design.objective`), so
shares of a few ppm are resolved by a few thousand engines.

Shell grades one at a time (:mod:`stackup.design.ladder`): the design of
``k`` grades starts from the design of ``k - 1`` with a grade split in two
(nested starts), and a design asked for more grades is never worse on
:math:`J` than the design of fewer (where no ``k``-grade design found does
better, the one of fewer grades is kept and its notes say so).

Check (:mod:`stackup.design.assess`): the designed scheme is scored again on
an independent check sample no decision saw; both figures are reported
(:attr:`Design.objective`, :attr:`Design.outside` on the design sample,
:attr:`Design.check` on the check sample, with 95 % intervals).

References
----------
.. [1] Mease, D., Nair, V. N., Sudjianto, A., "Selective assembly in
   manufacturing: statistical issues and optimal binning strategies",
   Technometrics 46 (2004) 165-175.
.. [2] ISO 13778:2017, Plain bearings - High-precision half bearings -
   Selective fitting.
"""

from ..patterns import ISO_SCHEMES
from .designer import SUPPLY_VOLUME, Design, design, scheme
from .problem import Weights

__all__ = ["Design", "ISO_SCHEMES", "SUPPLY_VOLUME", "Weights", "design", "scheme"]
