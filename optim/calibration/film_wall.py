"""The film_heating effect's two parameters: the film strength s and the wall condition w.

The loop's ``film_heating`` effect heats the film above the (lagged) oil by ``c P`` with
``c = s c_theory(w)``, ``c_theory(w) = delta (1 + 3w)/(12 k 2 pi R L)`` the smooth film's
first-order coefficient on the case's rotor-stator clearance (Nahme [1]_, through
:func:`oilgap.model.film_heating.film_theory_coefficient`). The fitted coefficient is the
film strength s, bounded to [0, 1] (1: the smooth-film theory). The wall condition w
(0: both walls at the oil's temperature, 1: an insulated rotor) is held at the case's
``[thermal] wall_floating`` (or its ``walls``; 0 without a ``[thermal]`` table) unless
the data identify it (:func:`wall_identifiability`).

Rule for w: the final model is refitted at w = 0, 1/2 and 1 (s free in [0, 1] at each)
and its leave-one-run-out RMSE taken, as for any effect [2]_. w is freed only if the
profile has an interior minimum that lies below *both* ends by the loop's acceptance
margin (the relative held-out gain every effect must bring); it is then taken at that
grid point. In the lumped film w enters only through ``s (1 + 3w)``: while s is free
below 1 the profile is flat (s absorbs w), and where the data need ``s (1 + 3w) > 1`` it
falls towards w = 1 and stays there; neither is an interior minimum, so on data of this
law w is held, with the profile and the reason in the identifiability block.

References
----------
.. [1] R. Nahme, "Beitraege zur hydrodynamischen Theorie der Lagerreibung",
   Ingenieur-Archiv 11:191-209, 1940.
.. [2] M. Stone, "Cross-validatory choice and assessment of statistical predictions",
   J. R. Stat. Soc. B 36:111-147, 1974.
"""

from __future__ import annotations

from dataclasses import replace
from typing import TYPE_CHECKING

import numpy as np

from oilgap.model.case import DesignCase
from oilgap.model.errors import InputError
from oilgap.model.film_heating import film_theory_coefficient, wall_floating_of
from oilgap.model.regions import joint_geometry

if TYPE_CHECKING:  # pragma: no cover - typing only
    from .refit import FinalModel, Refitter

WALL_GRID = (0.0, 0.5, 1.0)
"""Wall conditions w of the held-out profile [-]."""


def case_film_wall(case: DesignCase) -> float:
    """The wall condition w [-] the loop holds the film at unless the data identify it:
    the case's ``[thermal] wall_floating``, else 1 for ``walls = "adiabatic-rotor"``, else 0
    (isothermal walls, :func:`~oilgap.model.film_heating.wall_floating_of`).

    Parameters
    ----------
    case : DesignCase
        The rig's case (its ``[thermal]`` table, if any).

    Returns
    -------
    float
        w in [0, 1] [-].
    """
    th = case.thermal
    if th is None:
        return 0.0
    if th.wall_floating is not None:
        return float(th.wall_floating)
    return float(wall_floating_of(th.walls))


def case_film_theory_K_W(case: DesignCase, wall: float | None = None) -> float:
    """The film coefficient c of strength s = 1 on the case's rotor-stator clearance [K/W]:
    ``delta (1 + 3w)/(12 k 2 pi R L)`` (k = 0.13 W/(m K)) at the case's region-1 gap.

    Parameters
    ----------
    case : DesignCase
        The rig's case.
    wall : float, optional
        Wall condition w in [0, 1] [-] (default :func:`case_film_wall`).

    Returns
    -------
    float
        c_theory [K/W].

    References
    ----------
    Nahme [1]_ through :func:`~oilgap.model.film_heating.film_theory_coefficient`.
    """
    g = joint_geometry(case).regions[0]
    w = case_film_wall(case) if wall is None else float(wall)
    return float(film_theory_coefficient(float(np.max(g.gap_m)), g.radius_m, g.length_m, w))


def model_shapes(effects: dict, taylor_exponent: float, film_wall: float) -> dict:
    """The ``shapes`` entry of a model document: the Taylor-vortex exponent m [-] and the
    film's wall condition w [-] (its coefficient is the strength s), for the effects in it.

    Parameters
    ----------
    effects : dict
        Accepted effect -> coefficient.
    taylor_exponent : float
        m [-].
    film_wall : float
        w [-].

    Returns
    -------
    dict
        ``{"shapes": {...}}`` or empty.
    """
    shapes = {k: v for k, v in (
        ("taylor_vortex_onset", {"exponent": taylor_exponent}),
        ("film_heating", {"coefficient": "film_strength", "wall_floating": film_wall}),
    ) if k in effects}
    return {"shapes": shapes} if shapes else {}


def film_wall_of_doc(doc: dict, effects: dict) -> float:
    """The film's wall condition w [-] of a model document.

    Parameters
    ----------
    doc : dict
        The ``model`` block of ``loop.json``.
    effects : dict
        Its effects.

    Returns
    -------
    float
        w in [0, 1] [-] (0 without ``film_heating``).

    Raises
    ------
    InputError
        ``film_heating`` without ``shapes.film_heating`` (an older loop's c in K/W, not
        the strength s), or w outside [0, 1].
    """
    if "film_heating" not in effects:
        return 0.0
    shape = doc.get("shapes", {}).get("film_heating")
    if not isinstance(shape, dict) or shape.get("coefficient") != "film_strength":
        raise InputError("model.effects.film_heating", effects["film_heating"],
                         "the film strength s of this oilgap (a loop.json without "
                         "shapes.film_heating holds an older c in K/W: run oilgap loop again)")
    w = float(shape.get("wall_floating", 0.0))
    if not 0.0 <= w <= 1.0:
        raise InputError("model.shapes.film_heating.wall_floating", w, "in [0, 1]")
    return w


def _profile(refitter: Refitter, final: FinalModel, w_held: float) -> list[tuple]:
    """(w, held-out RMSE [W], s, fit, held-out) of the final model refitted at each w."""
    names = list(final.accepted)
    i = names.index("film_heating")
    y = refitter.model.samples.viscous_W
    out = []
    for w in WALL_GRID:
        refitter.model.film_wall = w
        th = final.fit.theta.copy()  # the same film coefficient c where s allows
        th[i] = min(1.0, th[i] * (1.0 + 3.0 * w_held) / (1.0 + 3.0 * w))
        fit = refitter.fit(names, final.fit.x, th)
        ho = refitter.leave_one_run_out(names, fit.x, fit.theta, fit)
        out.append((w, float(np.sqrt(np.mean((y - ho.pred) ** 2))), float(fit.theta[i]),
                    fit, ho))
    refitter.model.film_wall = w_held
    return out


def wall_identifiability(refitter: Refitter, final: FinalModel, w_held: float,
                         margin: float) -> tuple[FinalModel, float, str]:
    """The film's wall condition w: held (with the reason) or freed by the held-out rule.

    Parameters
    ----------
    refitter : Refitter
        The search's refitter (its forward model's ``film_wall`` is set to the result).
    final : FinalModel
        The final model at ``w_held``.
    w_held : float
        The case's wall condition (:func:`case_film_wall`) [-].
    margin : float
        The loop's acceptance margin: relative held-out gain [-].

    Returns
    -------
    (FinalModel, float, str)
        The final model (refitted at w if freed), w [-], and the statement for the
        identifiability block.

    References
    ----------
    Stone [2]_ (held-out choice); the rule in the module docstring.
    """
    where = f"held at w = {w_held:g} (the case's [thermal] wall condition, or isothermal walls)"
    if "film_heating" not in final.accepted:
        return final, w_held, f"{where}: film_heating is not in the model"
    prof = _profile(refitter, final, w_held)
    text = ", ".join(f"w = {w:g}: {h:.4g} W (s = {s:.3g})" for w, h, s, *_ in prof)
    ends = min(prof[0][1], prof[-1][1])
    best = min(prof[1:-1], key=lambda p: p[1])
    if best[1] < (1.0 - margin) * ends:
        refitter.model.film_wall = best[0]
        return (replace(final, fit=best[3], after=best[4]), best[0],
                f"fitted on the grid {WALL_GRID}: w = {best[0]:g}, the held-out RMSE profile "
                f"({text}) has its minimum inside, below both ends by more than the margin "
                f"{100 * margin:.0f} %")
    return final, w_held, (
        f"{where}: not identified, the held-out RMSE profile in w ({text}) has no interior "
        f"minimum below both ends by the margin {100 * margin:.0f} % (the lumped film depends "
        "on s (1 + 3w) only: s absorbs w below its bound)")
