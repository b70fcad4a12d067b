"""Stage 2 of the calibration: the forward model of the oil runs' viscous power.

:class:`ForwardModel` evaluates, for the samples of the oil runs, the seed
paper's clearance model (Eq. 8 per region through
:func:`~oilgap.model.regions.region_power`, region 1 with each sample's T and
gap, region 2 at T = 1) with the effects of the library added at given
coefficients. The joint's regions, the bearing pitch diameter and the rotor's
end-face radii come from :func:`~oilgap.model.regions.joint_geometry`; the
effect features from :func:`~oilgap.model.effects.effect_context`; the exact
shear-thinning form evaluates each region's law at the Cross apparent viscosity
(:func:`~oilgap.model.effects.cross_region_ratios`), in its Reynolds number too.

References
----------
.. [1] Seed paper, *Modeling and Optimization of Compensating Oil Viscous Power
   for a Deep-Sea Electric Manipulator*, Eqs. 5, 8 and 9.
.. [2] M. M. Cross, "Rheology of non-Newtonian fluids: a new flow equation for
   pseudoplastic systems", J. Colloid Sci. 20:417-437, 1965 (shear thinning).
.. [3] T. L. Bergman et al., *Fundamentals of Heat and Mass Transfer*, 7th ed.,
   Wiley 2011, sec. 5.2 (first-order lag of the gap oil temperature).
"""

from __future__ import annotations

import copy
import math
from dataclasses import replace

import numpy as np

from oilgap.model.case import DesignCase
from oilgap.model.effects import (
    EFFECTS,
    EffectContext,
    Precomputed,
    cross_region_ratios,
    effect_context,
    first_order_lag,
    taylor_feature,
)
from oilgap.model.elements import BearingElement, joint_elements
from oilgap.model.measured.data import TEMP_STEP_K, Samples
from oilgap.model.oil_state import (
    OilState,
    film_heated_oil_state,
    lagged_oil_state,
    measured_oil_state,
)
from oilgap.model.oils import Oil, normalize_oil_name
from oilgap.model.regions import JointGeometry, joint_geometry, region_power
from oilgap.model.skin_friction import FrictionLaw, groove_roughness_factor
from oilgap.model.taylor_couette import couette_floor_applies
from oilgap.model.units import celsius_to_kelvin

from .film_wall import case_film_theory_K_W

EXACT_FORMS = ("thermal_lag", "sensor_delay", "shear_thinning", "film_heating")
"""Effects refitted with their full nonlinear form (the regression feature is its first
order): the first-order lag of the oil temperature, the time shift of the power
record, the clearance law at the Cross apparent viscosity nu/(1 + lambda^2 gamma_dot^2)."""

TAYLOR_SHAPES = (0.5, 1.0, 2.0)
"""Shape exponents m of the Taylor-vortex excess ``(Ta/Ta_c)^m - 1`` screened: Wendt
1933's well-above-onset torque ~ Re^1.5 (m = 0.5), between, and Stuart 1958's near-onset
form (m = 2, the library's default)."""

SPEED_STEP = 1e-4
"""Relative speed step of the central difference dP/domega [-]."""

SHAPE_CACHE = 4
"""Law shapes whose region powers a forward model keeps (each is regions x samples)."""

COUETTE_ONLY = FrictionLaw(form="smooth", laminar_law="couette", scale=1e-12)
"""A law evaluated as exact laminar Couette everywhere: its scaled Eq. 6 lies below the
Couette floor of :func:`oilgap.model.skin_friction.moment_coefficient` at every Re."""

def sample_geometry(case: DesignCase, samples: Samples) -> JointGeometry:
    """The joint's regions with region 1 at each sample's roughness and gap.

    Parameters
    ----------
    case : DesignCase
        Rig geometry.
    samples : Samples
        Oil-run samples (``roughness_T`` [-] and ``gap1_m`` [m] per sample).

    Returns
    -------
    JointGeometry
        Regions, end-face radii [m] and bearing pitch diameter [m] (Eqs. 5, 9 [1]).
    """
    return joint_geometry(case, roughness_T=samples.roughness_T, gap1_m=samples.gap1_m)


def _run_indices(s: Samples) -> list[np.ndarray]:
    return [np.nonzero(s.run_code == c)[0] for c in np.unique(s.run_code)]


class ForwardModel:
    """Model viscous power [W] of a sample set for any friction law and effect coefficients.

    :meth:`power` gives Eq. 8 per region with the effects of ``coefs`` (name ->
    coefficient in the library's unit): thermal lag moves the oil temperature
    the viscosity follows (the oil's Walther line and density law are evaluated
    there) [3], shear thinning evaluates each region at its Cross apparent
    viscosity (Reynolds number included: ``P mu/mu_0`` only for laminar Couette flow) [2], sensor
    delay shifts the whole record in time, and the others add their library term.

    Parameters
    ----------
    samples : Samples
        Oil-run samples (SI arrays).
    case : DesignCase
        Rig geometry.
    oils : dict of str to Oil
        Oils by normalised name (their temperature laws serve the thermal lag).
    taylor_exponent : float
        Shape exponent m of the Taylor-vortex excess [-] (default 2: Stuart's form).

    Attributes
    ----------
    samples : Samples
    case : DesignCase
    geometry : JointGeometry
        Regions with region 1 at each sample's T and gap [m].
    runs : list of arrays
        Sample indices of each run.
    oil_groups : list of (array, Oil)
        Samples whose viscosity follows each oil's temperature law.
    taylor_exponent : float
        Shape exponent m of the Taylor-vortex excess (:data:`TAYLOR_SHAPES`) [-].
    film_wall : float
        Wall condition w in [0, 1] of the ``film_heating`` effect (0 isothermal walls,
        1 insulated rotor) [-]: the film coefficient is ``s`` times
        :attr:`film_theory_K_W`.
    """

    def __init__(self, samples: Samples, case: DesignCase, oils: dict[str, Oil],
                 taylor_exponent: float = 2.0, film_wall: float = 0.0):
        s = samples
        self.taylor_exponent = float(taylor_exponent)
        self.film_wall = float(film_wall)
        self._film_c0: float | None = None  # c_theory at w = 0 [K/W]
        self.samples = s
        self.case = case
        self.geometry = sample_geometry(case, s)
        self.runs = _run_indices(s)
        law_rows = np.isfinite(s.nu_pm[0])
        uniq, inv = np.unique(s.oil.astype(str), return_inverse=True)
        keys = np.array([normalize_oil_name(o) for o in uniq])[inv]
        self.oil_groups = [(np.nonzero((keys == k) & law_rows)[0], oils[k])
                           for k in np.unique(keys[law_rows]) if k in oils]
        self._static: dict[str, np.ndarray] = {}
        self._shapes: dict[tuple, list[np.ndarray]] = {}  # law shape -> region powers
        self.measured = measured_oil_state(celsius_to_kelvin(s.temp_C), s.nu_m2_s,
                                           s.density_kg_m3)
        self._lags: dict[float, OilState] = {}  # thermal-lag tau -> the lagged oil state
        self._features: dict[tuple, np.ndarray] = {}  # (effect, lag state key) -> feature
        self._film_start: dict[float, tuple] = {}  # lag -> (c, last film temperature [K])
        self._film_rise: dict[float, np.ndarray] = {}  # lag -> its rise over the base per c [W]
        self.fixed_elements = tuple(e for e in joint_elements(case)  # a linear drive's
                                    if not isinstance(e, BearingElement))

    @property
    def film_theory_K_W(self) -> float:
        """The film coefficient c of strength s = 1 at the wall condition :attr:`film_wall`
        on the case's rotor-stator clearance [K/W]: ``delta (1 + 3w)/(12 k 2 pi R L)``
        (:func:`~oilgap.model.film_heating.film_theory_coefficient`; the case's gap, so
        that a fitted model predicts any rows with the coefficient it was fitted with)."""
        if self._film_c0 is None:
            self._film_c0 = case_film_theory_K_W(self.case, 0.0)
        return self._film_c0 * (1.0 + 3.0 * self.film_wall)

    def subset(self, mask: np.ndarray) -> ForwardModel:
        """Forward model of the samples where ``mask`` holds.

        Parameters
        ----------
        mask : array of bool
            Samples kept [-].

        Returns
        -------
        ForwardModel
            Sharing the cached law-independent features, restricted to ``mask``.
        """
        sub = copy.copy(self)
        sub.samples = s = self.samples.subset(mask)
        sub.geometry = sample_geometry(self.case, s)
        sub.runs = _run_indices(s)
        pos = np.cumsum(mask) - 1
        sub.oil_groups = [(pos[idx[mask[idx]]], oil) for idx, oil in self.oil_groups]
        sub._static = {k: v[mask] for k, v in self._static.items()}
        sub.measured = measured_oil_state(celsius_to_kelvin(s.temp_C), s.nu_m2_s,
                                          s.density_kg_m3)
        sub._shapes, sub._lags, sub._features, sub._film_start = {}, {}, {}, {}
        sub._film_rise = {}
        return sub

    def region_powers(self, law: FrictionLaw, omega=None, nu=None, rho=None
                      ) -> list[np.ndarray]:
        """Viscous power [W] per region and sample (Eq. 8 through ``region_power`` [1]).

        Parameters
        ----------
        law : FrictionLaw
            Friction law of every region.
        omega, nu, rho : arrays, optional
            Speed [rad/s], kinematic viscosity [m^2/s] and density [kg/m^3] per
            sample (default: the samples').

        Returns
        -------
        list of arrays
            Region 1, then region 2 if the rig has one [W].
        """
        s = self.samples
        state = self._state_key(nu, rho)
        if (omega is None or omega is s.omega) and state is not False:
            return self._law_powers(law, state)
        omega = s.omega if omega is None else omega
        nu = s.nu_m2_s if nu is None else nu
        rho = s.density_kg_m3 if rho is None else rho
        return [region_power(r, omega, nu, rho, law) for r in self.geometry.regions]

    def _state_key(self, nu, rho):
        """None: the samples' own oil state; tau: a kept thermal-lag state; False: other."""
        s = self.samples
        if (nu is None or nu is s.nu_m2_s) and (rho is None or rho is s.density_kg_m3):
            return None
        return next((t for t, st in self._lags.items()
                     if st.nu_m2_s is nu and st.density_kg_m3 is rho), False)

    def _lagged_state(self, tau_s: float) -> OilState:
        """The oil state at the temperature lagging by ``tau_s`` [3] (the last few kept)."""
        if tau_s not in self._lags:
            if len(self._lags) >= SHAPE_CACHE:
                self._lags.pop(next(iter(self._lags)))
            self._lags[tau_s] = lagged_oil_state(
                self.measured, tau_s, celsius_to_kelvin(self.lagged_temperature(tau_s)),
                self.oil_properties)
        return self._lags[tau_s]

    def oil_state(self, law: FrictionLaw, coefs: dict | None = None) -> OilState:
        """The one oil state of the samples under ``law`` and the effects ``coefs``.

        Measured without thermal effect; lagged by ``coefs["thermal_lag"]`` [s] [3];
        film-heated by ``coefs["film_heating"]``, the film strength s [-], at ``c = s``
        :attr:`film_theory_K_W` [K/W] (from the lagged temperature
        when both are in, the film's loss the clearance's under ``law``, shear
        thinning included). Every viscosity-dependent term of :meth:`power` reads it.

        Parameters
        ----------
        law : FrictionLaw
            Friction law of the clearance model (the film's loss).
        coefs : dict, optional
            Effect name -> coefficient in the library's unit.

        Returns
        -------
        OilState
            Temperatures [K], viscosities [m^2/s] and densities [kg/m^3] per sample.
        """
        coefs = coefs or {}
        tau = float(coefs.get("thermal_lag", 0.0))
        state = self._lagged_state(tau) if tau else self.measured
        c = float(coefs.get("film_heating", 0.0)) * self.film_theory_K_W
        if not c > 0.0:
            return state
        lam2 = max(0.0, float(coefs.get("shear_thinning", 0.0)))
        ratios = (cross_region_ratios(self._bare_context(state), math.sqrt(lam2))
                  if lam2 else [1.0] * len(self.geometry.regions))

        def power_at(nu, rho):  # the film's own loss: the clearance's, thinned if thinning
            s = self.samples
            return sum(region_power(r, s.omega, nu * q, rho, law)
                       for r, q in zip(self.geometry.regions, ratios, strict=True))

        film = film_heated_oil_state(state, c, power_at, self.oil_properties,
                                     self._film_warm_start(tau, state, c))
        self._film_start[tau] = (c, film.temp_film_K)  # warm start of the next iteration
        self._film_rise[tau] = (film.temp_film_K - state.temp_lagged_K) / c
        for d in (self._film_start, self._film_rise):  # the last few lags only
            while len(d) > SHAPE_CACHE:
                d.pop(next(iter(d)))
        return film

    def _film_warm_start(self, tau: float, state: OilState, c: float) -> np.ndarray | None:
        """A film temperature near the root at lag ``tau`` and film coefficient ``c`` [K]:
        the last solution at this lag and coefficient, else the base plus ``c`` times the
        film rise per unit coefficient of this lag or of the nearest lag solved (each fit
        iteration moves c, each cross-validation fold the lag; the rise is nearly ``c P``,
        and P hardly moves with either). The film solver keeps a warm start only if its
        Newton steps converge to 1e-11 K."""
        if tau in self._film_start and self._film_start[tau][0] == c:
            return self._film_start[tau][1]
        if not self._film_rise:
            return None
        near = min(self._film_rise, key=lambda t: abs(t - tau))
        return state.temp_lagged_K + c * self._film_rise[near]

    def _bare_context(self, state: OilState, powers=None) -> EffectContext:
        """Effect context at an oil state, law-independent features only (no region power
        unless ``powers`` are given)."""
        s = self.samples
        pw = powers if powers is not None else [np.zeros(s.n)] * len(self.geometry.regions)
        return effect_context(self.geometry, s.omega, s.domega_dt, state.nu_m2_s,
                              state.density_kg_m3, None,
                              given=Precomputed(powers_W=pw, dtemp_dt_K_s=s.dtemp_dt), oil=state)

    def state_feature(self, name: str, state: OilState) -> np.ndarray:
        """Feature of a law-independent effect (disc, bearing, seal, inertia) at ``state``.

        Parameters
        ----------
        name : str
            Library effect.
        state : OilState
            The oil state its viscosity and density are read at.

        Returns
        -------
        array
            Power per unit coefficient [W/unit] (measured and lagged states cached).
        """
        if state is self.measured:
            return self.static_feature(name)
        key = None if state.key is None else (name, state.key)
        if key is not None and key in self._features:
            return self._features[key]
        f = EFFECTS[name].feature_values(self._bare_context(state))
        if key is not None:
            if len(self._features) >= 4 * SHAPE_CACHE:
                self._features.pop(next(iter(self._features)))
            self._features[key] = f
        return f

    def _law_powers(self, law: FrictionLaw, state=None) -> list[np.ndarray]:
        """Region powers at the samples' speed and a kept oil state [W]. The law's scale
        (C of the power law) and T^gamma multiply the power (Eq. 8 [1]), so the rest of
        it, its shape, is evaluated once per (form, laminar law, transition, alpha, beta,
        oil state) and kept (the last few)."""
        unit = replace(law, scale=1.0, C=1.0, gamma=0.0)
        key = (unit.form, unit.laminar_law, unit.transition, unit.alpha, unit.beta,
               unit.branch_C, unit.branch_alpha, unit.branch_beta, state)
        if key not in self._shapes:
            s = self.samples
            st = self.measured if state is None else self._lags[state]
            nu, rho = st.nu_m2_s, st.density_kg_m3
            if len(self._shapes) >= SHAPE_CACHE:
                self._shapes.pop(next(iter(self._shapes)))
            self._shapes[key] = [region_power(r, s.omega, nu, rho, unit)
                                 for r in self.geometry.regions]
        k = law.C if law.form == "power-law" else law.scale
        g = [1.0 if law.gamma == 0.0 else groove_roughness_factor(r.roughness_T, law.gamma)
             for r in self.geometry.regions]
        out = [p * (k if law.gamma == 0.0 else k * gi)
               for gi, p in zip(g, self._shapes[key], strict=True)]
        if couette_floor_applies(law):  # a scale < 1 stops at exact Couette (issue 27)
            out = [np.maximum(p, f * gi) for p, f, gi in zip(
                out, self._couette_powers(state), g, strict=True)]
        return out

    def _couette_powers(self, state=None) -> list[np.ndarray]:
        """Region powers of exact laminar Couette flow, the floor of every law [W] (kept)."""
        key = ("couette floor", state)
        if key not in self._shapes:
            st = self.measured if state is None else self._lags[state]
            if len(self._shapes) >= SHAPE_CACHE:
                self._shapes.pop(next(iter(self._shapes)))
            self._shapes[key] = [region_power(r, self.samples.omega, st.nu_m2_s,
                                              st.density_kg_m3, COUETTE_ONLY)
                                 for r in self.geometry.regions]
        return self._shapes[key]

    def couette_power(self) -> np.ndarray:
        """Viscous power of exact laminar Couette flow in every region [W] per sample: the
        least any clearance flow of this geometry dissipates (Helmholtz-Korteweg).

        Returns
        -------
        array
            Sum over the regions [W].
        """
        return sum(self._couette_powers())

    def base_power(self, law: FrictionLaw) -> np.ndarray:
        """Viscous power of all regions [W] per sample, no effect.

        Parameters
        ----------
        law : FrictionLaw

        Returns
        -------
        array
            Sum of :meth:`region_powers` [W].
        """
        return self._with_fixed(sum(self.region_powers(law)), self.samples.nu_m2_s,
                                self.samples.density_kg_m3)

    def _with_fixed(self, total, nu, rho):
        """``total`` plus the linear drive's elements (screw, rod guide, passages) at the
        samples' motor speed and the oil state (nu, rho) [W]; ``total`` as it is for a
        rotary joint (:func:`~oilgap.model.elements.joint_elements`)."""
        for e in self.fixed_elements:
            total = total + e.power(self.samples.omega, nu, rho)
        return total

    def _power_derivatives(self, law: FrictionLaw) -> tuple[np.ndarray, np.ndarray]:
        """dP/dt [W/s] along the record and dP/dT [W/K] (NaN without a temperature law)."""
        s = self.samples
        h = SPEED_STEP
        w = np.where(np.abs(s.omega) > 0, s.omega, 1.0)
        dP_dw = (sum(self.region_powers(law, omega=s.omega * (1 + h)))
                 - sum(self.region_powers(law, omega=s.omega * (1 - h)))) / (2 * h * w)
        dP_dT = np.full(s.n, np.nan)
        ok = np.isfinite(s.nu_pm[0]) & np.isfinite(s.nu_pm[1])
        if ok.any():
            nu_m, nu_p = (np.where(ok, x, s.nu_m2_s) for x in s.nu_pm)
            rho_m, rho_p = (np.where(ok, x, s.density_kg_m3) for x in s.rho_pm)
            d = (sum(self.region_powers(law, nu=nu_p, rho=rho_p))
                 - sum(self.region_powers(law, nu=nu_m, rho=rho_m))) / (2 * TEMP_STEP_K)
            dP_dT = np.where(ok, d, np.nan)
        dP_dt = dP_dw * s.domega_dt + np.nan_to_num(dP_dT) * s.dtemp_dt
        return dP_dt, dP_dT

    def context(self, law: FrictionLaw, derivatives: bool = True, nu=None, rho=None,
                state: OilState | None = None) -> EffectContext:
        """Effect context of the samples under ``law``.

        Parameters
        ----------
        law : FrictionLaw
        derivatives : bool
            Compute dP/dt [W/s] (central difference in speed) and dP/dT [W/K]
            (through nu(T), rho(T)); zero if False.
        nu, rho : arrays, optional
            Oil properties per sample [m^2/s], [kg/m^3] (default: ``state``'s).
        state : OilState, optional
            The oil state every term reads (default: the measured one).

        Returns
        -------
        EffectContext
        """
        s = self.samples
        state = self.measured if state is None else state
        nu = state.nu_m2_s if nu is None else nu
        rho = state.density_kg_m3 if rho is None else rho
        pw = self.region_powers(law, nu=nu, rho=rho)
        slopes = {}
        if derivatives:
            dP_dt, dP_dT = self._power_derivatives(law)
            slopes = {"dpower_dt_W_s": dP_dt, "dpower_dtemp_W_K": dP_dT}
        given = Precomputed(powers_W=pw, dtemp_dt_K_s=s.dtemp_dt, **slopes)
        return effect_context(self.geometry, s.omega, s.domega_dt, nu, rho, law, given=given,
                              oil=state)

    def oil_properties(self, temp_K: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Viscosity [m^2/s] and density [kg/m^3] at the oil temperature ``temp_K`` [K].

        Parameters
        ----------
        temp_K : array
            Oil temperature per sample [K].

        Returns
        -------
        (nu, rho)
            Per sample, from each oil's Walther line and density law; unchanged where
            the row has no temperature law (a per-row override).
        """
        nu = self.samples.nu_m2_s.copy()
        rho = self.samples.density_kg_m3.copy()
        for idx, oil in self.oil_groups:
            nu[idx], _, rho[idx] = oil.properties(temp_K[idx], 0.0)
        return nu, rho

    def lagged_temperature(self, tau_s: float) -> np.ndarray:
        """Oil temperature [degC] lagging (tau > 0) or leading (tau < 0) the measured one [3].

        Parameters
        ----------
        tau_s : float
            Time constant of the first-order lag [s].

        Returns
        -------
        array
            Temperature per sample [degC].
        """
        s = self.samples
        if tau_s < 0:
            return s.temp_C - tau_s * s.dtemp_dt
        out = np.empty(s.n)
        for idx in self.runs:
            out[idx] = first_order_lag(s.time_s[idx], s.temp_C[idx], tau_s)
        return out

    def static_feature(self, name: str) -> np.ndarray:
        """Feature of an effect that does not depend on the friction law (cached).

        Parameters
        ----------
        name : str
            Library effect.

        Returns
        -------
        array
            Power per unit coefficient [W/unit].
        """
        if name not in self._static:
            ctx = self.context(FrictionLaw(form="power-law"), derivatives=False)
            self._static[name] = EFFECTS[name].feature_values(ctx)
        return self._static[name]

    def _thinned_powers(self, law: FrictionLaw, ctx: EffectContext, lam_s: float
                        ) -> list[np.ndarray]:
        """Region powers [W] at the Cross apparent viscosity of each region [2]: the
        clearance law evaluated at ``nu mu/mu_0`` (its Reynolds number included), which
        is ``P mu/mu_0`` only in laminar Couette flow."""
        ratios = cross_region_ratios(ctx, lam_s)
        return [region_power(r, ctx.omega_rad_s, ctx.nu_m2_s * q, ctx.density_kg_m3, law)
                for r, q in zip(self.geometry.regions, ratios, strict=True)]

    def power(self, law: FrictionLaw, coefs: dict | None = None) -> np.ndarray:
        """Model viscous power [W] per sample.

        Parameters
        ----------
        law : FrictionLaw
            Friction law of the clearance model (Eq. 8 [1]).
        coefs : dict, optional
            Effect name -> coefficient in the library's unit.

        Returns
        -------
        array
            Power [W] per sample.
        """
        coefs = coefs or {}
        s = self.samples
        state = self.oil_state(law, coefs)  # the one oil state every term below reads
        total = 0.0
        lam2 = max(0.0, coefs.get("shear_thinning", 0.0))
        if lam2 or coefs.get("taylor_vortex_onset", 0.0):  # effects that need the context
            ctx = self.context(law, derivatives=False, state=state)
            pw = [r.power_W for r in ctx.regions]
        else:
            pw = self.region_powers(law, nu=state.nu_m2_s, rho=state.density_kg_m3)
        if lam2:  # the thinned viscosity enters each region's Reynolds number too
            pw = self._thinned_powers(law, ctx, math.sqrt(lam2))
        for p in pw:
            total = total + p
        total = self._with_fixed(total, state.nu_m2_s, state.density_kg_m3)
        for name, c in coefs.items():
            if name in EXACT_FORMS or c == 0.0:
                continue
            f = taylor_feature(ctx, self.taylor_exponent) if name == "taylor_vortex_onset" \
                else self.state_feature(name, state)
            total = total + c * f
        d = coefs.get("sensor_delay", 0.0)
        if d:
            out = np.empty(s.n)
            for idx in self.runs:
                t = s.time_s[idx]
                out[idx] = np.interp(t - d, t, total[idx])
            total = out
        return np.asarray(total, dtype=float) * np.ones(s.n)
