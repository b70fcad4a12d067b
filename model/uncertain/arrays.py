"""The joint's loss over arrays of uncertain inputs (one number per row).

:func:`joint_loss_arrays` gives, for every row of broadcast input arrays (names of
:data:`~oilgap.model.uncertain.inputs.INPUTS`), the same number as the scalar reference
path ``operating_temperature(apply_inputs(case, row), mode).mean_power_W`` (the total of
:func:`~oilgap.model.evaluation.evaluate_case`): the regions' cycle-mean loss and the
rolling bearing's, under a thermal mode.

References
----------
.. [1] Seed paper, Eqs. 5, 6, 8 and 10 (the isothermal loss over the cycle).
.. [2] T. L. Bergman et al., *Fundamentals of Heat and Mass Transfer*, 7th ed., Wiley
   2011, sec. 3.1 (the bulk balance).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

import numpy as np

from ..errors import InputError, SolverError
from ..joint_loss import operating_temperature, resolve_thermal_mode
from .inputs import INPUTS, apply_inputs

if TYPE_CHECKING:  # pragma: no cover - typing only
    from ..case import DesignCase


def broadcast_inputs(inputs: Mapping[str, np.ndarray]) -> tuple[dict[str, np.ndarray], tuple]:
    """The inputs as float arrays of one broadcast shape, names checked.

    Parameters
    ----------
    inputs : mapping
        Input name (:data:`INPUTS`) -> value(s) in its unit.

    Returns
    -------
    arrays : dict
        Name -> float array of the common shape.
    shape : tuple
        The broadcast shape.

    Raises
    ------
    InputError
        An unknown name, or arrays that do not broadcast.
    """
    for k in inputs:
        if k not in INPUTS:
            raise InputError("uncertainty input", k, f"one of {', '.join(INPUTS)}")
    arrs = {k: np.asarray(v, dtype=float) for k, v in inputs.items()}
    try:
        shape = np.broadcast_shapes(*(a.shape for a in arrs.values()))
    except ValueError:
        raise InputError("uncertainty inputs", {k: a.shape for k, a in arrs.items()},
                         "arrays of shapes that broadcast together") from None
    return {k: np.broadcast_to(a, shape) for k, a in arrs.items()}, shape


def joint_loss_arrays(case: DesignCase, inputs: Mapping[str, np.ndarray], mode=None,
                      strict: bool = False) -> np.ndarray:
    """Cycle-mean loss [W] of the joint (regions and bearing) for each row of inputs.

    Row ``i`` equals ``operating_temperature(apply_inputs(case, row_i), mode)
    .mean_power_W`` (the ``total_mean_power_W`` of
    :func:`~oilgap.model.evaluation.evaluate_case` under that mode).

    Parameters
    ----------
    case : DesignCase
        The nominal case.
    inputs : mapping
        Input name (:data:`INPUTS`) -> array (or float) in its unit; all broadcast
        together; missing inputs keep the case's value.
    mode : str or ThermalMode, optional
        Thermal mode (default: the case's,
        :func:`~oilgap.model.joint_loss.default_thermal_mode`).
    strict : bool
        Raise :class:`SolverError` at the first row without a result (a heat balance
        without a root below the cap) instead of giving it NaN.

    Returns
    -------
    ndarray
        Loss [W], the inputs' broadcast shape; NaN where a row has no result.

    Raises
    ------
    InputError
        An unknown input, an out-of-range value (as :func:`apply_inputs`), or a mode the
        case cannot take.
    SolverError
        ``strict`` and a row without a result.

    References
    ----------
    Seed paper [1]_ (Eqs. 5, 10); Bergman et al. [2]_ (the balance).
    """
    mode = resolve_thermal_mode(case, None if mode is None else str(mode))
    arrs, shape = broadcast_inputs(inputs)
    flat = {k: a.ravel() for k, a in arrs.items()}
    n = int(np.prod(shape, dtype=np.int64))
    out = np.full(n, np.nan)
    for i in range(n):
        c = apply_inputs(case, {k: float(a[i]) for k, a in flat.items()})
        try:
            out[i] = operating_temperature(c, mode).mean_power_W
        except SolverError:
            if strict:
                raise
    return out.reshape(shape)


__all__ = ["broadcast_inputs", "joint_loss_arrays"]
