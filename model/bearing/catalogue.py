"""Rolling-bearing designations, product data and the ``[bearing]`` table of a case.

* :func:`parse_designation`: ISO 15 / SKF designations of deep-groove ball bearings
  ("61809", "6809" = 61809, "6205", "62/22", "618/500", "608") into series and bore.
* :data:`PRODUCTS`: catalogue rows (d, D, B, C, C_0, speeds) of the bearings near the
  seed's size, from the transcription of SKF catalogue 10000 EN [1]_.
* :func:`ball_set_estimate`: number and diameter of the balls, an APPROXIMATION (SKF
  does not publish them; neither friction model needs them).
* :func:`bearing_spec_from`: a :class:`~oilgap.model.bearing.BearingSpec` from a
  ``[bearing]`` table, every default it fills in named in ``defaults_used``;
  :func:`bearing_table` writes back what the user gave.

The SKF series constants (R1, R2, S1, S2, K_Z) are
:data:`oilgap.model.bearing.laws.SERIES_CONSTANTS`, re-exported here.

References
----------
.. [1] SKF, *Rolling bearings*, catalogue 10000 EN (2013), deep-groove ball bearing
   tables, as transcribed in github.com/JRaposo-m/SKF-Bearing-Selection-Tool
   (``skf_model/bearings/data/deep_groove_ball/deep_groove_ball.csv``), read.
.. [2] ISO 15:2017, *Rolling bearings -- Radial bearings -- Boundary dimensions, general
   plan* (bore codes, dimension series; recalled, standard practice).
.. [3] ISO 3290-1:2014, *Rolling bearings -- Balls* (ball sizes in 1/32 inch steps).
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

from ..errors import InputError, check_finite
from ..units import MM_TO_M, m_to_mm
from .friction import DRAG_CHOICES, KINDS, BearingSpec
from .laws import (
    MU_BL_DEFAULT,
    MU_EHL_MINERAL,
    SERIES_CONSTANTS,
    iso_static_load_rating,
)

__all__ = ["SERIES_CONSTANTS", "ProductRow", "PRODUCTS", "ParsedDesignation",
           "parse_designation", "ball_set_estimate", "bearing_spec_from", "bearing_table",
           "describe_defaults", "BEARING_KEYS", "DEFAULT_RADIAL_LOAD_N"]

SERIES_ALIASES = {"68": "618", "69": "619"}
"""Old designations of the thin-section series: 68xx = 618xx, 69xx = 619xx [-]."""
BORE_CODES = {"00": 10.0, "01": 12.0, "02": 15.0, "03": 17.0}
"""ISO 15 bore codes below 04 [mm]; from 04 the bore is 5 x code [2]_."""
CLEARANCE_SUFFIXES = ("C2", "CN", "C3", "C4", "C5")
"""Radial-clearance suffixes, accepted and ignored (no effect on either model) [-]."""
_SEAL_RE = re.compile(r"^2?(Z|ZZ|RZ|RS|RS1|RS2|RSH|RSL|LLU|LLB|DDU|VV|LU|DU)$")
DEFAULT_RADIAL_LOAD_N = 50.0
"""Radial load when none is given [N]: the research notes' guess for the seed joint (the
loss hardly depends on it: elasticity 0.02 at the seed point, docs/bearing.md)."""
BALL_STEP_MM = 25.4 / 32.0
"""Ball-size step of the estimate: 1/32 inch [mm] [3]_."""
SEAL_MESSAGE = ("an open bearing: an oil-filled joint's bearing runs open and submerged, and "
                "seal moments are not modelled (SKF's seal constants K_S1, K_S2 and beta "
                "are not available here)")


@dataclass(frozen=True)
class ProductRow:
    """Catalogue data of one open deep-groove ball bearing [1]_.

    Attributes
    ----------
    designation : str
        SKF designation [-].
    bore_mm, outside_mm, width_mm : float
        d, D, B [mm].
    dynamic_rating_kN, static_rating_kN : float
        Basic dynamic and static load ratings C, C_0 [kN].
    reference_speed_rpm, limiting_speed_rpm : float
        Reference and limiting speed [rpm].
    """

    designation: str
    bore_mm: float
    outside_mm: float
    width_mm: float
    dynamic_rating_kN: float
    static_rating_kN: float
    reference_speed_rpm: float
    limiting_speed_rpm: float


PRODUCTS: dict[str, ProductRow] = {r.designation: r for r in (
    ProductRow(
        designation="61807", bore_mm=35, outside_mm=47, width_mm=7, dynamic_rating_kN=4.36,
        static_rating_kN=3.35, reference_speed_rpm=30000, limiting_speed_rpm=18000),
    ProductRow(
        designation="61808", bore_mm=40, outside_mm=52, width_mm=7, dynamic_rating_kN=4.49,
        static_rating_kN=3.75, reference_speed_rpm=26000, limiting_speed_rpm=16000),
    ProductRow(
        designation="61809", bore_mm=45, outside_mm=58, width_mm=7, dynamic_rating_kN=6.63,
        static_rating_kN=6.10, reference_speed_rpm=22000, limiting_speed_rpm=14000),
    ProductRow(
        designation="61810", bore_mm=50, outside_mm=65, width_mm=7, dynamic_rating_kN=6.76,
        static_rating_kN=6.80, reference_speed_rpm=20000, limiting_speed_rpm=13000),
    ProductRow(
        designation="61811", bore_mm=55, outside_mm=72, width_mm=9, dynamic_rating_kN=9.04,
        static_rating_kN=8.8, reference_speed_rpm=19000, limiting_speed_rpm=12000),
    ProductRow(
        designation="61812", bore_mm=60, outside_mm=78, width_mm=10, dynamic_rating_kN=11.9,
        static_rating_kN=11.4, reference_speed_rpm=17000, limiting_speed_rpm=11000),
    ProductRow(
        designation="61909", bore_mm=45, outside_mm=68, width_mm=12, dynamic_rating_kN=14.0,
        static_rating_kN=10.8, reference_speed_rpm=20000, limiting_speed_rpm=13000),
    ProductRow(
        designation="16009", bore_mm=45, outside_mm=75, width_mm=10, dynamic_rating_kN=16.5,
        static_rating_kN=10.8, reference_speed_rpm=20000, limiting_speed_rpm=12000),
    ProductRow(
        designation="6009", bore_mm=45, outside_mm=75, width_mm=16, dynamic_rating_kN=22.1,
        static_rating_kN=14.6, reference_speed_rpm=20000, limiting_speed_rpm=12000),
    ProductRow(
        designation="6209", bore_mm=45, outside_mm=85, width_mm=19, dynamic_rating_kN=35.1,
        static_rating_kN=21.6, reference_speed_rpm=17000, limiting_speed_rpm=11000),
    ProductRow(
        designation="6309", bore_mm=45, outside_mm=100, width_mm=25, dynamic_rating_kN=55.3,
        static_rating_kN=31.5, reference_speed_rpm=15000, limiting_speed_rpm=9500),
)}
"""Open deep-groove ball bearings of SKF 10000 EN [1]_ (61808-61810 are the notes'; the
others were read from the same transcription), by designation."""


@dataclass(frozen=True)
class ParsedDesignation:
    """A designation split into series and bore [2]_.

    Attributes
    ----------
    designation : str
        Canonical form (``"6809"`` -> ``"61809"``) [-].
    series : str
        Dimension series, a key of :data:`SERIES_CONSTANTS` [-].
    bore_mm : float
        Bore d [mm].
    """

    designation: str
    series: str
    bore_mm: float


def _suffix_check(text: str, suffix: str, where: str) -> None:
    for token in (t for t in re.split(r"[-/\s]+", suffix) if t):
        if token in CLEARANCE_SUFFIXES:
            continue
        if _SEAL_RE.match(token):
            raise InputError("designation", text, SEAL_MESSAGE, where)
        raise InputError("designation", text, f"a deep-groove ball bearing designation "
                         f"without suffix {token!r} (clearance suffixes "
                         f"{', '.join(CLEARANCE_SUFFIXES)} are accepted)", where)


def parse_designation(text: str, where: str = "[bearing]") -> ParsedDesignation:
    """Series and bore of a deep-groove ball bearing designation [2]_.

    The last two digits are the bore code (00 -> 10, 01 -> 12, 02 -> 15, 03 -> 17 mm,
    from 04 code x 5 mm); ``/d`` gives the bore directly (``62/22``, ``618/500``);
    three-digit miniatures carry it in their last digit (``608`` -> 60 series, 8 mm);
    ``68xx``/``69xx`` are ``618xx``/``619xx``. Clearance suffixes (C3) are ignored; seal
    and shield suffixes (2RS1, 2Z) are refused.

    Parameters
    ----------
    text : str
        The designation [-].
    where : str
        Where it came from, for messages.

    Returns
    -------
    ParsedDesignation
        Canonical designation [-], series [-], bore [mm].

    Raises
    ------
    InputError
        Not a deep-groove ball bearing designation oilgap knows, or a sealed one.
    """
    if not isinstance(text, str):
        raise InputError("designation", text, "a string such as \"6809\"", where)
    mt = re.match(r"^\s*(\d+)(?:/(\d+(?:\.\d+)?))?(.*)$", text.upper())
    if mt is None:
        raise InputError("designation", text, "digits such as \"61809\", \"6205\" or "
                         "\"62/22\"", where)
    digits, slash, suffix = mt.groups()
    _suffix_check(text, suffix, where)
    if slash is not None:
        series, bore, code = digits, float(slash), "/" + slash
    elif len(digits) == 3 and digits[0] == "6":
        series, bore, code = digits[:2], float(digits[2]), digits[2]
    elif len(digits) in (3, 4, 5):
        series, code = digits[:-2], digits[-2:]
        bore = BORE_CODES.get(code, 5.0 * int(code))
    else:
        raise InputError("designation", text, "a series and a bore code (\"61809\", "
                         "\"6205\", \"62/22\")", where)
    series = SERIES_ALIASES.get(series, series)
    if series not in SERIES_CONSTANTS:
        raise InputError("designation", text, "a deep-groove ball bearing series: "
                         f"{', '.join(SERIES_CONSTANTS)} (68 = 618, 69 = 619)", where)
    if bore <= 0.0:
        raise InputError("designation", text, "a bore > 0", where)
    return ParsedDesignation(series + code, series, bore)


def ball_set_estimate(bore_mm: float, outside_mm: float) -> tuple[int, float]:
    """Number and diameter of the balls of a deep-groove bearing: an APPROXIMATION.

    ``D_w = 0.3 (D - d)`` rounded to the nearest 1/32 inch [3]_, ``Z = 0.6 pi dm/D_w``
    rounded (Conrad bearings fill about 60 % of the pitch circle). For 61809 it gives
    24 x 3.969 mm, whose ISO 76 C_0 is within 1 % of the catalogue's; rough for other
    sizes (docs/bearing.md). Neither friction model uses Z or D_w.

    Parameters
    ----------
    bore_mm, outside_mm : float
        d and D [mm].

    Returns
    -------
    balls : int
        Z [-].
    ball_diameter_mm : float
        D_w [mm].
    """
    dw = max(1, round(0.3 * (outside_mm - bore_mm) / BALL_STEP_MM)) * BALL_STEP_MM
    balls = max(3, round(0.6 * math.pi * 0.5 * (bore_mm + outside_mm) / dw))
    return int(balls), dw


BEARING_KEYS = ("name", "model", "type", "designation", "series", "bore_mm", "outside_mm",
                "width_mm", "balls", "ball_diameter_mm", "radial_load_N", "axial_load_N",
                "static_load_rating_N", "submerged", "oil_level_mm", "f0", "drag", "mu_ehl",
                "mu_bl", "k_rs", "seals")
"""Keys of a ``[bearing]`` table [-]."""


def _number(table, key, where, default, used, positive=False):
    if key not in table:
        used.append(key)
        return default
    x = check_finite(key, table[key], where)
    if x < 0.0 or (positive and x == 0.0):
        raise InputError(key, table[key], "a number > 0" if positive else "a number >= 0",
                         where)
    return x


def _geometry(table: dict, where: str, used: list) -> dict:
    """Designation, series, d, D, B, C_0 and the ball set, from the table or the catalogue."""
    parsed = (parse_designation(table["designation"], where) if "designation" in table
              else None)
    row = PRODUCTS.get(parsed.designation) if parsed else None
    series = table.get("series", parsed.series if parsed else None)
    series = SERIES_ALIASES.get(str(series), series) if series is not None else None
    if parsed and series != parsed.series:
        raise InputError("series", table["series"], f"{parsed.series!r}, the series of "
                         f"designation {table['designation']!r}", where)
    bore = _number(table, "bore_mm", where, parsed.bore_mm if parsed else None, [], True)
    if bore is None:
        raise InputError("bore_mm", None, "a bore in mm, or a designation", where)
    if parsed and bore != parsed.bore_mm:
        raise InputError("bore_mm", table["bore_mm"], f"{parsed.bore_mm:g}, the bore of "
                         f"designation {table['designation']!r}", where)
    outside = _number(table, "outside_mm", where, row.outside_mm if row else None, used, True)
    if outside is None:
        what = f"designation {parsed.designation} is not" if parsed else "no designation is"
        raise InputError("outside_mm", None, f"an outside diameter in mm: {what} in the "
                         f"built-in catalogue ({', '.join(PRODUCTS)})", where)
    if row and outside != row.outside_mm:
        raise InputError("outside_mm", table["outside_mm"], f"{row.outside_mm:g}, the "
                         f"catalogue's for {row.designation}", where)
    width = _number(table, "width_mm", where, row.width_mm if row else None,
                    used if row else [], True)
    est_balls, est_dw = ball_set_estimate(bore, outside)
    dw = _number(table, "ball_diameter_mm", where, est_dw, used, True)
    balls = table.get("balls")
    if balls is None:
        used.append("balls")
        balls = max(3, round(0.6 * math.pi * 0.5 * (bore + outside) / dw))
    c0 = _number(table, "static_load_rating_N", where,
                 row.static_rating_kN * 1e3 if row else None, used, True)
    if c0 is None and isinstance(balls, int) and not isinstance(balls, bool):
        c0 = iso_static_load_rating(balls, dw, 0.5 * (bore + outside))
    return {"designation": parsed.designation if parsed else None, "series": series,
            "bore_m": bore * MM_TO_M, "outside_m": outside * MM_TO_M,
            "width_m": None if width is None else width * MM_TO_M, "balls": balls,
            "ball_diameter_m": dw * MM_TO_M, "static_load_rating_N": c0}


MODEL_KEYS = {"palmgren": ("f0",), "skf": ("drag", "mu_ehl", "mu_bl", "k_rs")}
"""The ``[bearing]`` keys only one friction model reads [-]: Palmgren's f_0; SKF's drag
terms, sliding coefficients and replenishment constant."""


def _model_keys(table: dict, model: str, where: str) -> None:
    """A key the chosen model does not read is refused naming the key and the model."""
    for owner, keys in MODEL_KEYS.items():
        if model == owner or model not in MODEL_KEYS:
            continue
        for key in keys:
            if key in table:
                raise InputError(key, table[key], f"only with model = '{owner}'; the model is "
                                 f"{model!r}, which has no {key} (remove the key, or set "
                                 f"model = '{owner}')", where)


def _choice_key(table, key, default, used):
    if key not in table:
        used.append(key)
        return default
    return table[key]


def bearing_spec_from(table: dict, where: str = "[bearing]") -> BearingSpec:
    """A bearing from a ``[bearing]`` table, defaults filled in and named.

    Keys (:data:`BEARING_KEYS`): ``model`` (skf | palmgren, default skf), ``type``
    (deep-groove-ball), ``designation`` or ``bore_mm`` + ``outside_mm`` (+ ``series``
    for skf), ``width_mm``, ``balls``, ``ball_diameter_mm``, ``radial_load_N`` (default
    50), ``axial_load_N`` (0), ``static_load_rating_N`` (catalogue, or ISO 76 from the
    balls), ``submerged`` (true; false with ``oil_level_mm``), ``f0`` (4 submerged, 2 oil
    bath), ``drag`` (skf-vm-term | skf-full | none, default skf-vm-term; the former
    vm | vm+rs read with a deprecation warning), ``mu_ehl`` (0.05), ``mu_bl`` (0.12),
    ``k_rs`` (0 submerged, 3e-8 oil bath), ``seals`` (only "none"). Everything taken
    from the catalogue or a default is listed in ``defaults_used``, except the series
    and bore a designation states exactly.

    Parameters
    ----------
    table : dict
        The ``[bearing]`` table [keys with their units: mm, N].
    where : str
        Where it came from, for messages.

    Returns
    -------
    BearingSpec
        The bearing [SI].

    Raises
    ------
    InputError
        An unknown key, a bad value (naming its key), a sealed bearing, a designation
        whose outside diameter is not in :data:`PRODUCTS` without ``outside_mm``.
    """
    if not isinstance(table, dict):
        raise InputError("bearing", table, "a table of keys", where)
    for key in table:
        if key not in BEARING_KEYS:
            raise InputError(key, table[key], f"a [bearing] key: {', '.join(BEARING_KEYS)}",
                             where)
    if table.get("seals", "none") not in ("none", False):
        raise InputError("seals", table["seals"], "'none': " + SEAL_MESSAGE, where)
    used: list[str] = []
    geo = _geometry(table, where, used)
    model = _choice_key(table, "model", "skf", used)
    _model_keys(table, model, where)
    kind = _choice_key(table, "type", KINDS[0], used)
    level = _number(table, "oil_level_mm", where, None, [], True)
    submerged = _choice_key(table, "submerged", level is None, used)
    f0 = _number(table, "f0", where, None, used, True)
    k_rs = _number(table, "k_rs", where, None, used)
    fr = _number(table, "radial_load_N", where, DEFAULT_RADIAL_LOAD_N, used)
    fa = _number(table, "axial_load_N", where, 0.0, used)
    name = table.get("name", geo["designation"] or "bearing")
    return BearingSpec(
        name=str(name), model=model, kind=kind, radial_load_N=fr, axial_load_N=fa,
        submerged=submerged, oil_level_m=None if level is None else level * MM_TO_M,
        f0=f0, k_rs=k_rs, drag=_choice_key(table, "drag", DRAG_CHOICES[0], used),
        mu_ehl=_number(table, "mu_ehl", where, MU_EHL_MINERAL, used),
        mu_bl=_number(table, "mu_bl", where, MU_BL_DEFAULT, used),
        defaults_used=tuple(k for k in BEARING_KEYS if k in used), **geo)


def _mm(x_m):
    return float(f"{m_to_mm(x_m):.12g}")


def bearing_table(spec: BearingSpec) -> dict:
    """The ``[bearing]`` table of a spec: the keys the user gave, not the defaults.

    ``bearing_spec_from(bearing_table(spec))`` gives the spec back.

    Parameters
    ----------
    spec : BearingSpec
        The bearing.

    Returns
    -------
    dict
        TOML key -> value [mm, N, -].
    """
    values = {"model": spec.model, "type": spec.kind, "series": spec.series,
              "bore_mm": _mm(spec.bore_m), "outside_mm": _mm(spec.outside_m),
              "width_mm": None if spec.width_m is None else _mm(spec.width_m),
              "balls": spec.balls, "ball_diameter_mm": _mm(spec.ball_diameter_m),
              "radial_load_N": spec.radial_load_N, "axial_load_N": spec.axial_load_N,
              "static_load_rating_N": spec.static_load_rating_N, "submerged": spec.submerged,
              "oil_level_mm": None if spec.oil_level_m is None else _mm(spec.oil_level_m),
              "f0": spec.f0, "drag": spec.drag, "mu_ehl": spec.mu_ehl, "mu_bl": spec.mu_bl,
              "k_rs": spec.k_rs}
    out = {}
    if spec.name != (spec.designation or "bearing"):
        out["name"] = spec.name
    if spec.designation is not None:
        out["designation"] = spec.designation
        values.pop("series")
        values.pop("bore_mm")
    for key, v in values.items():
        if key not in spec.defaults_used and v is not None:
            out[key] = v
    return out


def describe_defaults(spec: BearingSpec) -> tuple[str, ...]:
    """One line per default the tool filled in, with its value and basis (for outputs).

    Parameters
    ----------
    spec : BearingSpec
        The bearing.

    Returns
    -------
    tuple of str
        ``"key = value (basis)"`` [units of the key].
    """
    row = PRODUCTS.get(spec.designation or "")
    cat = f"catalogue {row.designation}" if row else ""
    basis = {
        "model": ("skf", "SKF frictional-moment model"),
        "type": (spec.kind, "the only type implemented"),
        "outside_mm": (_mm(spec.outside_m), cat),
        "width_mm": (None if spec.width_m is None else _mm(spec.width_m), cat),
        "balls": (spec.balls, "estimate: 60 % of the pitch circle filled; not used by "
                  "SKF or Palmgren, only by the band's balls in still oil"),
        "ball_diameter_mm": (_mm(spec.ball_diameter_m), "estimate: 0.3 (D - d) to 1/32 in; "
                             "not used by SKF or Palmgren, only by the band's balls in "
                             "still oil"),
        "static_load_rating_N": (spec.static_load_rating_N, cat or "ISO 76 from the "
                                 "estimated balls"),
        "radial_load_N": (spec.radial_load_N, "guess; the loss hardly depends on it"),
        "axial_load_N": (spec.axial_load_N, "none"),
        "submerged": (spec.submerged, "an oil-filled joint"),
        "f0": (spec.f0, "Palmgren, 2x the oil-bath value 2 (recalled guidance)"
               if spec.submerged else "Palmgren, oil bath"),
        "drag": (spec.drag, "only the V_M term of SKF's drag, not SKF's full model: its "
                 "R_s term is outside its validity in a submerged bearing; balls as spheres "
                 "in still oil give about the same drag; docs/bearing.md"),
        "mu_ehl": (spec.mu_ehl, "SKF, mineral oil"),
        "mu_bl": (spec.mu_bl, "SKF 2013"),
        "k_rs": (spec.k_rs, "flooded (submerged)" if spec.submerged
                 else "SKF, low-level oil bath"),
    }
    return tuple(f"{k} = {basis[k][0]} ({basis[k][1]})" for k in spec.defaults_used
                 if k in basis)

