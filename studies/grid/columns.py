"""The grid's vocabulary: the parameter columns a grid may hold and the result columns.

Plain data, no imports: the command line's ``study sweep`` help text lists these
columns without loading pandas or the engine.
"""

ENGINE_VERSION = "2"
"""Part of every point key: bump it when a result column changes meaning."""

PARAM_COLUMNS: dict[str, str] = {
    "oil": "oil name (catalogue, e.g. VG22, or the case's/--oils table)",
    "oil_temp_C": "oil temperature [degC]",
    "depth_m": "sea depth [m]",
    "T1_mm": "rotor groove-bottom radius [mm]",
    "T2_mm": "rotor outer radius [mm]",
    "T3_mm": "stator bore radius [mm]",
    "T4_mm": "stator groove-bottom radius [mm]",
    "length_mm": "region-1 length L [mm]",
    "R_mm": "region-1 radius R = T2 [mm]; shifts T1..T4 together (gap and grooves kept)",
    "gap_mm": "region-1 clearance delta = T3 - T2 [mm]; moves the stator (T3, T4)",
    "T": "roughness (T4-T1)/(T3-T2) [-], >= 1; groove depths scaled in their rotor/stator "
         "proportion (even split if the case has none)",
    "gamma": "groove-roughness exponent of Eq. 8 [-]",
    "scale": "multiplier on the Eq. 6 C_m [-]",
    "laminar_law": "couette or bilgen-boulos",
    "form": "bilgen-boulos, smooth or power-law",
    "peak_speed_rpm": "peak speed of the case's sine duty cycle [rpm]",
    "region2_radius_mm": "bearing annulus radius [mm]",
    "region2_length_mm": "bearing annulus length [mm]",
    "region2_gap_mm": "bearing annulus gap [mm]",
    "sea_temp_C": "sea temperature [degC] (thermal full only; replaces the case's [thermal] "
                  "sea_temp_C; the oil temperature is then a result)",
    "resistance_K_per_W": "thermal resistance oil to sea [K/W] (thermal full only)",
    "label": "free text carried through to the results (not a parameter)",
}
"""Columns a grid may hold in ``mode="evaluate"`` (and ``"optimize"``)."""

OPTIMIZE_COLUMNS: dict[str, str] = {
    "torque_min_Nm": "required torque capability of the motor [N m]",
    "delta_min_mm": "lower bound of the magnetic gap delta [mm]",
    "delta_max_mm": "upper bound of the magnetic gap delta [mm]",
    "inertia_max_ratio": "rotor inertia limit as a multiple of the case's rotor [-]",
}
"""Extra columns a grid may hold in ``mode="optimize"`` (passed to the design NLP)."""

THERMAL_COLUMNS = ("sea_temp_C", "resistance_K_per_W")
"""Columns of the heat balance: only under the thermal mode ``full``."""

OPERATING_COLUMNS = ("oil", "oil_temp_C", "depth_m")
"""In optimize mode these are parameters of the NLP (no rebuild of the problem)."""

STRING_COLUMNS = ("oil", "laminar_law", "form", "label")

EVALUATE_NUMBERS = ("mean_power_W", "region1_power_W", "region2_power_W",
                    "isothermal_power_W", "oil_temp_op_C", "sea_temp_C", "nu_cSt",
                    "density_kg_m3", "Re1_peak", "Re2_peak", "T_res", "delta_mm_res",
                    "R_mm_res", "L_mm_res")
"""The numbers of one evaluated point (see :func:`oilgap.studies.grid.evaluate.evaluate_cases`):
``mean_power_W`` under the thermal mode, ``isothermal_power_W`` the seed's isothermal loss
at the row's given temperature (the oil's, or the sea's under ``full``),
``oil_temp_op_C`` the operating bulk temperature (a result under ``full``),
``sea_temp_C`` (``full`` only), ``nu_cSt`` and ``density_kg_m3`` at ``oil_temp_op_C``."""

EVALUATE_RESULTS = ("status", "error", "warning", "thermal_mode", *EVALUATE_NUMBERS)
"""Result columns of ``mode="evaluate"``; ``*_res`` are the resolved geometry of the row."""

OPTIMIZE_RESULTS = ("status", "error", "warning", "thermal_mode", "mean_power_W",
                    "mean_power_exact_W", "oil_temp_op_C",
                    "initial_mean_power_W", "region1_power_W", "region2_power_W", "delta_mm",
                    "R_mm", "L_mm", "T1_mm", "T2_mm", "T3_mm", "T4_mm", "T",
                    "torque_capability_Nm", "inertia_kgm2", "inertia_ratio",
                    "torque_min_Nm_used", "inertia_max_kgm2_used", "active_constraints",
                    "iterations", "solve_time_s")
"""Result columns of ``mode="optimize"``: the optimal design; ``mean_power_W`` is the
NLP objective (smooth C_m), ``mean_power_exact_W`` the same design with the case's
exact C_m form under the thermal mode, ``oil_temp_op_C`` its operating bulk temperature."""

MODES = ("evaluate", "optimize")


def result_columns(mode: str) -> tuple[str, ...]:
    """The result columns of ``mode`` ("evaluate" or "optimize")."""
    return EVALUATE_RESULTS if mode == "evaluate" else OPTIMIZE_RESULTS
