"""Physical laws of the candidate effects the seed's viscous-loss model leaves out.

Pure functions of floats, numpy arrays and, where they are closed-form, CasADi
symbols; :mod:`oilgap.model.effects` turns them into the regression features of
the candidate-effect library (and re-exports them):

* :func:`disc_reynolds`, :func:`free_disc_moment_coefficient`,
  :func:`end_face_disc_power`: rotor end faces as free discs (laminar boundary
  layer ``C_m = 3.87 Re_r^-0.5``, turbulent ``0.146 Re_r^-0.2`` above 3e5) [1], [2].
* :func:`enclosed_disc_couette_power`: end faces in a narrow axial clearance s
  (laminar Couette disc, torque ``pi mu omega (r_o^4 - r_i^4) / (2 s)`` per face) [1], [3].
  Not a candidate of the loop: it scales as ``mu omega^2`` and does not depend
  on T, exactly like the bearing region's laminar loss, so on any data it is
  absorbed into the fitted C (see :data:`oilgap.model.effects.CONFOUNDED_FORMS`).
* :func:`ball_churning_power`: load-independent (viscous) friction moment of a rolling
  bearing in oil [4], [5], through :func:`oilgap.model.bearing.laws.palmgren_viscous_moment`
  (re-exported here with ``PALMGREN_MIN_NU_N``): the one Palmgren law, shared with the
  ``palmgren`` bearing model, so a fitted coefficient is Palmgren's f_0.
* :func:`coulomb_friction_power`: seal (lip or face) Coulomb friction [6].
* :func:`oil_inertia_power`: kinetic-energy rate of entrained oil.
* :func:`first_order_lag`, :func:`thermal_lag_power`: gap oil temperature as a
  first-order lag of the measured temperature [7].
* :func:`taylor_excess_factor`, :func:`taylor_vortex_power`: torque excess above
  the critical Taylor number [8], [9], [10], [13].
* :func:`couette_shear_rate`, :func:`cross_viscosity_ratio`,
  :func:`shear_thinning_power`: Cross/Carreau shear thinning [11], [12].
* :func:`sensor_delay_power`: a power reading that lags the speed reading.

References
----------
.. [1] J. Pyrhönen, T. Jokinen, V. Hrabovcová, *Design of Rotating Electrical
   Machines*, 2nd ed., Wiley 2014, sec. 9.5 (rotor end-face friction loss,
   ``P = C_M rho Omega^3 (D^5 - D_i^5) / 64``).
.. [2] H. Schlichting, K. Gersten, *Boundary-Layer Theory*, 9th ed., Springer
   2017, sec. 5.3.3 (rotating disc, ``C_M = 3.87 / Re^0.5`` both sides).
.. [3] J. W. Daily, R. E. Nece, "Chamber dimension effects on induced flow and
   frictional resistance of enclosed rotating disks", ASME J. Basic Eng. 82:217,
   1960 (regime I, merged boundary layers: Couette disc).
.. [4] A. Palmgren, *Ball and Roller Bearing Engineering*, 3rd ed., Burbank 1959.
.. [5] T. A. Harris, M. N. Kotzalas, *Essential Concepts of Bearing Technology*,
   5th ed., CRC 2006, ch. 9 (``M_0 = 1e-7 f_0 (nu n)^(2/3) d_m^3`` [N mm]).
.. [6] H. K. Müller, B. S. Nau, *Fluid Sealing Technology*, Marcel Dekker 1998,
   ch. 5 (lip-seal friction torque, nearly speed-independent).
.. [7] T. L. Bergman, A. S. Lavine, F. P. Incropera, D. P. DeWitt, *Fundamentals
   of Heat and Mass Transfer*, 7th ed., Wiley 2011, sec. 5.2 (lumped capacitance).
.. [8] G. I. Taylor, Phil. Trans. R. Soc. A 223:289-343, 1923.
.. [9] J. T. Stuart, "On the non-linear mechanics of hydrodynamic stability",
   J. Fluid Mech. 4:1-21, 1958 (torque excess proportional to Ta^2 - Ta_c^2
   near onset, Ta^2 being the classical Taylor number).
.. [10] R. J. Donnelly, "Experiments on the stability of viscous flow between
   rotating cylinders I. Torque measurements", Proc. R. Soc. A 246:312, 1958.
.. [11] M. M. Cross, "Rheology of non-Newtonian fluids: a new flow equation for
   pseudoplastic systems", J. Colloid Sci. 20:417-437, 1965.
.. [12] R. B. Bird, R. C. Armstrong, O. Hassager, *Dynamics of Polymeric
   Liquids*, vol. 1, 2nd ed., Wiley 1987, sec. 4.4 (Carreau model).
.. [13] F. Wendt, "Turbulente Strömungen zwischen zwei rotierenden konaxialen
   Zylindern", Ing.-Arch. 4:577-595, 1933 (torque ~ Re^1.5 well above onset
   against the laminar ~ Re: an excess ~ (Ta/Ta_c)^0.5 - 1 in the seed's Ta).
"""

from __future__ import annotations

import numpy as np
from scipy.signal import lfilter

from .. import _math as m
from ..bearing.friction import palmgren_viscous_torque
from ..bearing.laws import PALMGREN_MIN_NU_N, palmgren_viscous_moment  # noqa: F401 (re-export)
from ..taylor_couette import CRITICAL_TAYLOR_NUMBER

FREE_DISC_TRANSITION_RE = 3.0e5
"""Disc Reynolds number of the laminar-turbulent change of the free-disc law [1]."""



def disc_reynolds(omega_rad_s, radius_m, nu_m2_s):
    """Disc Reynolds number ``Re_r = |omega| r^2 / nu`` [-] [1].

    Parameters
    ----------
    omega_rad_s : float, array or CasADi symbol
        Disc speed [rad/s] (sign ignored).
    radius_m : float, array or CasADi symbol
        Disc (outer) radius r [m].
    nu_m2_s : float, array or CasADi symbol
        Kinematic viscosity [m^2/s].

    Returns
    -------
    float, array or CasADi expression
        Disc Reynolds number [-].

    References
    ----------
    Pyrhönen et al. [1], sec. 9.5.
    """
    return m.fabs(omega_rad_s) * radius_m * radius_m / nu_m2_s


def free_disc_moment_coefficient(disc_re):
    """Moment coefficient of a free disc, both faces [-] [1], [2].

    ``C_M = 3.87 Re_r^-0.5`` (laminar boundary layer, Re_r < 3e5),
    ``0.146 Re_r^-0.2`` above. Re_r is floored at 1e-12.

    Parameters
    ----------
    disc_re : float, array or CasADi symbol
        Disc Reynolds number Re_r [-] (:func:`disc_reynolds`).

    Returns
    -------
    float, array or CasADi expression
        Moment coefficient C_M [-] (both faces).

    References
    ----------
    Pyrhönen et al. [1], sec. 9.5; Schlichting & Gersten [2], sec. 5.3.3.
    """
    re = m.fmax(disc_re, 1.0e-12)
    return m.where(re < FREE_DISC_TRANSITION_RE, 3.87 * re**-0.5, 0.146 * re**-0.2)


def end_face_disc_power(omega_rad_s, nu_m2_s, density_kg_m3, r_outer_m, r_inner_m):
    """Friction power [W] of both rotor end faces turning as free discs in oil.

    ``P = C_M rho |omega|^3 (D^5 - D_i^5) / 64`` with ``C_M`` from
    :func:`free_disc_moment_coefficient` at ``Re_r = |omega| r_o^2 / nu`` [1], [2].
    In the laminar range ``P ∝ rho nu^0.5 |omega|^2.5``.

    Parameters
    ----------
    omega_rad_s : float, array or CasADi symbol
        Rotor speed [rad/s] (sign ignored).
    nu_m2_s : float, array or CasADi symbol
        Kinematic viscosity [m^2/s].
    density_kg_m3 : float, array or CasADi symbol
        Oil density [kg/m^3].
    r_outer_m, r_inner_m : float
        Outer radius (D = 2 r_o) and inner radius (D_i = 2 r_i) of the faces [m].

    Returns
    -------
    float, array or CasADi expression
        Power of both faces [W].

    References
    ----------
    Pyrhönen et al. [1], sec. 9.5; Schlichting & Gersten [2], sec. 5.3.3.
    """
    cm = free_disc_moment_coefficient(disc_reynolds(omega_rad_s, r_outer_m, nu_m2_s))
    w = m.fabs(omega_rad_s)
    d5 = (2.0 * r_outer_m) ** 5 - (2.0 * r_inner_m) ** 5
    return cm * density_kg_m3 * w * w * w * d5 / 64.0


def enclosed_disc_couette_power(omega_rad_s, mu_Pa_s, r_outer_m, r_inner_m, axial_gap_m,
                                faces=2):
    """Friction power [W] of end faces in a narrow axial clearance (laminar Couette disc).

    Torque per face ``pi mu omega (r_o^4 - r_i^4) / (2 s)`` [3]; power = torque x omega
    x faces, i.e. ``∝ mu omega^2``. Confounded with the laminar clearance law
    (see the module docstring), so not a candidate effect.

    Parameters
    ----------
    omega_rad_s : float, array or CasADi symbol
        Rotor speed [rad/s] (sign ignored).
    mu_Pa_s : float, array or CasADi symbol
        Dynamic viscosity [Pa s].
    r_outer_m, r_inner_m : float
        Outer and inner radius of the faces [m].
    axial_gap_m : float
        Axial clearance s between face and housing [m].
    faces : int
        Number of faces [-].

    Returns
    -------
    float, array or CasADi expression
        Power [W].

    References
    ----------
    Daily & Nece [3] (regime I); Pyrhönen et al. [1].
    """
    w = m.fabs(omega_rad_s)
    return faces * np.pi * mu_Pa_s * w * w * (r_outer_m**4 - r_inner_m**4) / (2.0 * axial_gap_m)


def ball_churning_power(omega_rad_s, nu_m2_s, pitch_diameter_m, f0=1.0):
    """Viscous (churning) loss [W] of a rolling bearing in oil: ``M_0 |omega|`` [4], [5].

    :func:`oilgap.model.bearing.laws.palmgren_viscous_moment` (the one Palmgren law) converted
    to SI; ``∝ nu^(2/3) |omega|^(5/3)``. With ``f0 = 1`` a fitted coefficient is f_0,
    i.e. a correction factor on the ``palmgren`` bearing model.

    Parameters
    ----------
    omega_rad_s : float, array or CasADi symbol
        Rotor speed [rad/s] (sign ignored).
    nu_m2_s : float, array or CasADi symbol
        Kinematic viscosity [m^2/s].
    pitch_diameter_m : float
        Bearing pitch diameter d_m [m].
    f0 : float
        Palmgren factor [-].

    Returns
    -------
    float, array or CasADi expression
        Power [W].

    References
    ----------
    Palmgren [4]; Harris & Kotzalas [5], ch. 9.
    """
    return palmgren_viscous_torque(omega_rad_s, nu_m2_s, pitch_diameter_m, f0) \
        * m.fabs(omega_rad_s)


def coulomb_friction_power(omega_rad_s, torque_Nm):
    """Coulomb (seal) friction loss [W]: ``tau_c |omega|`` [6].

    Parameters
    ----------
    omega_rad_s : float, array or CasADi symbol
        Rotor speed [rad/s] (sign ignored).
    torque_Nm : float
        Friction torque tau_c [N m].

    Returns
    -------
    float, array or CasADi expression
        Power [W].

    References
    ----------
    Müller & Nau [6], ch. 5.
    """
    return torque_Nm * m.fabs(omega_rad_s)


def oil_inertia_power(omega_rad_s, domega_dt_rad_s2, density_kg_m3, volume_inertia_m5):
    """Power [W] to accelerate entrained oil: ``rho I_V omega domega/dt``.

    ``I_V = ∫ r^2 dV`` [m^5] of the oil that turns with the rotor, so the
    entrained inertia is ``J = rho I_V`` [kg m^2]; the power is the rate of
    change of its kinetic energy ``J omega^2 / 2`` (zero mean over a cycle).

    Parameters
    ----------
    omega_rad_s : float, array or CasADi symbol
        Rotor speed [rad/s] (signed).
    domega_dt_rad_s2 : float, array or CasADi symbol
        Angular acceleration [rad/s^2].
    density_kg_m3 : float, array or CasADi symbol
        Oil density [kg/m^3].
    volume_inertia_m5 : float
        Second moment of the entrained oil volume I_V [m^5].

    Returns
    -------
    float, array or CasADi expression
        Power [W] (negative while the oil slows down).

    References
    ----------
    Rate of change of kinetic energy, ``d/dt (J omega^2 / 2)``.
    """
    return density_kg_m3 * volume_inertia_m5 * omega_rad_s * domega_dt_rad_s2


def first_order_lag(time_s, signal, tau_s, initial=None):
    """Exact response [same unit as signal] of a first-order lag ``tau dy/dt = x - y``.

    The input is taken as piecewise linear between samples, for which the
    discrete update is exact [7]:
    ``y_k+1 = x_k+1 + (y_k - x_k) e^(-h/tau) - s tau (1 - e^(-h/tau))`` with
    ``s = (x_k+1 - x_k)/h``; on a uniform record this is an IIR filter
    (``scipy.signal.lfilter``). Starts from ``initial`` (default: the first
    input, i.e. in equilibrium). numpy only; ``tau_s = 0`` returns the input.

    Parameters
    ----------
    time_s : array
        Sample times [s], increasing.
    signal : array
        Input x [any unit].
    tau_s : float
        Time constant tau [s] (> 0, or 0 for no lag).
    initial : float, optional
        Output at the first sample [unit of signal].

    Returns
    -------
    ndarray
        Output y at the sample times [unit of signal].

    References
    ----------
    Bergman et al. [7], sec. 5.2.
    """
    t = np.asarray(time_s, dtype=float)
    x = np.asarray(signal, dtype=float)
    if tau_s == 0.0 or len(x) < 2:
        return x.copy()
    y0 = x[0] if initial is None else float(initial)
    dt = np.diff(t)
    h = float(np.median(dt))
    if np.all(np.abs(dt - h) <= 1e-9 * max(1.0, h)):
        e = np.exp(-h / tau_s)
        g = tau_s / h * (1.0 - e)
        b = np.array([1.0 - g, g - e])
        a = np.array([1.0, -e])
        # state so that y_0 = y0 given x_0: y_1 = e y_0 + b0 x_1 + b1 x_0
        y = np.empty_like(x)
        y[0] = y0
        y[1:], _ = lfilter(b, a, x[1:], zi=np.array([e * y0 + b[1] * x[0]]))
        return y
    y = np.empty_like(x)
    y[0] = y0
    for k in range(len(x) - 1):
        e = np.exp(-dt[k] / tau_s)
        s = (x[k + 1] - x[k]) / dt[k]
        y[k + 1] = x[k + 1] + (y[k] - x[k]) * e - s * tau_s * (1.0 - e)
    return y


def thermal_lag_power(dpower_dtemp_W_K, dtemp_dt_K_s, tau_s):
    """Power change [W] when the gap oil lags the measured temperature by ``tau`` [s].

    ``T_oil ≈ T_meas - tau dT_meas/dt`` (first term of the first-order lag [7]), so
    ``dP ≈ -tau (dP/dT) dT/dt``. tau < 0: the measured temperature lags the oil.

    Parameters
    ----------
    dpower_dtemp_W_K : float or array
        Derivative of the viscous power with respect to the oil temperature [W/K].
    dtemp_dt_K_s : float or array
        Rate of change of the measured temperature [K/s].
    tau_s : float
        Lag of the gap oil behind the measurement [s].

    Returns
    -------
    float or array
        Power change [W].

    References
    ----------
    Bergman et al. [7], sec. 5.2 (first term of the first-order lag).
    """
    return -tau_s * dpower_dtemp_W_K * dtemp_dt_K_s


def taylor_excess_factor(taylor, critical=CRITICAL_TAYLOR_NUMBER, exponent=2.0):
    """Supercriticality ``max(0, (Ta/Ta_c)^m - 1)`` [-] of Taylor-vortex flow [8], [9], [13].

    Ta is the seed's Eq. 3 (``∝ omega``). Two published shapes: near onset the
    torque excess grows linearly in the classical Taylor number Ta^2 (Stuart
    [9], Donnelly [10]): ``m = 2`` (the default); well above onset Wendt's
    torque ~ Re^1.5 against the laminar ~ Re [13] makes the excess grow like
    ``(Ta/Ta_c)^0.5``: ``m = 0.5``.

    Parameters
    ----------
    taylor : float, array or CasADi symbol
        Taylor number of the seed's Eq. 3 [-].
    critical : float
        Critical Taylor number [-] (41.3).
    exponent : float
        Shape exponent m [-] (> 0; 2: Stuart near onset, 0.5: Wendt).

    Returns
    -------
    float, array or CasADi expression
        Supercriticality [-] (0 below onset).

    References
    ----------
    Taylor [8]; Stuart [9]; Donnelly [10]; Wendt [13]; seed paper (Modeling and
    Optimization of Compensating Oil Viscous Power for a Deep-Sea Electric
    Manipulator, Eq. 3).
    """
    r = taylor / critical
    if exponent == 2.0:
        return m.fmax(r * r - 1.0, 0.0)
    return m.fmax(m.fmax(r, 0.0) ** exponent - 1.0, 0.0)


def taylor_vortex_power(power_laminar_W, taylor, k, critical=CRITICAL_TAYLOR_NUMBER,
                        exponent=2.0):
    """Extra loss [W] of Taylor vortices: ``k P_lam max(0, (Ta/Ta_c)^m - 1)`` [8]-[13].

    Parameters
    ----------
    power_laminar_W : float, array or CasADi symbol
        Viscous power of the clearance model [W].
    taylor : float, array or CasADi symbol
        Taylor number [-].
    k : float
        Torque excess per unit supercriticality [-].
    critical : float
        Critical Taylor number [-].
    exponent : float
        Shape exponent m [-] (2: Stuart near onset [9], 0.5: Wendt [13]).

    Returns
    -------
    float, array or CasADi expression
        Extra power [W].

    References
    ----------
    Taylor [8]; Stuart [9]; Donnelly [10]; Wendt [13].
    """
    return k * power_laminar_W * taylor_excess_factor(taylor, critical, exponent)


def couette_shear_rate(omega_rad_s, radius_m, gap_m):
    """Nominal shear rate ``|omega| R / delta`` [1/s] of a narrow clearance [12].

    Parameters
    ----------
    omega_rad_s : float, array or CasADi symbol
        Rotor speed [rad/s] (sign ignored).
    radius_m : float, array or CasADi symbol
        Rotor radius R [m].
    gap_m : float, array or CasADi symbol
        Radial clearance delta [m].

    Returns
    -------
    float, array or CasADi expression
        Shear rate [1/s].

    References
    ----------
    Bird, Armstrong & Hassager [12] (simple shear in a narrow gap).
    """
    return m.fabs(omega_rad_s) * radius_m / gap_m


def cross_viscosity_ratio(shear_rate_1_s, lam_s, exponent=2.0):
    """Cross model ``mu/mu_0 = 1 / (1 + (lambda gamma_dot)^m)`` [-] (mu_inf = 0) [11].

    Parameters
    ----------
    shear_rate_1_s : float, array or CasADi symbol
        Shear rate gamma_dot [1/s].
    lam_s : float
        Cross time constant lambda [s].
    exponent : float
        Cross exponent m [-].

    Returns
    -------
    float, array or CasADi expression
        Viscosity ratio [-].

    References
    ----------
    Cross [11].
    """
    return 1.0 / (1.0 + (lam_s * shear_rate_1_s) ** exponent)


def carreau_viscosity_ratio(shear_rate_1_s, lam_s, n):
    """Carreau model ``mu/mu_0 = (1 + (lambda gamma_dot)^2)^((n-1)/2)`` [-] [12].

    Parameters
    ----------
    shear_rate_1_s : float, array or CasADi symbol
        Shear rate gamma_dot [1/s].
    lam_s : float
        Carreau time constant lambda [s].
    n : float
        Power-law index [-] (1: Newtonian).

    Returns
    -------
    float, array or CasADi expression
        Viscosity ratio [-].

    References
    ----------
    Bird, Armstrong & Hassager [12], sec. 4.4.
    """
    return (1.0 + (lam_s * shear_rate_1_s) ** 2) ** ((n - 1.0) / 2.0)


def shear_thinning_power(power_laminar_W, shear_rate_1_s, lam2_s2):
    """Power change [W] of a shear-thinning oil at low Weissenberg number [11], [12].

    ``dP ≈ -lambda^2 gamma_dot^2 P_lam``: the first term of the Cross model with
    m = 2 (Carreau: lambda^2 stands for (1-n) lambda^2 / 2).

    Parameters
    ----------
    power_laminar_W : float or array
        Viscous power of the Newtonian model [W].
    shear_rate_1_s : float or array
        Nominal shear rate [1/s] (:func:`couette_shear_rate`).
    lam2_s2 : float
        lambda^2 [s^2], >= 0.

    Returns
    -------
    float or array
        Power change [W] (<= 0).

    References
    ----------
    Cross [11]; Bird, Armstrong & Hassager [12].
    """
    return -lam2_s2 * shear_rate_1_s * shear_rate_1_s * power_laminar_W


def sensor_delay_power(dpower_dt_W_s, delay_s):
    """Power change [W] when the power reading lags the speed reading by ``d`` [s].

    ``P(t - d) ≈ P(t) - d dP/dt`` (first-order Taylor expansion of the time shift).

    Parameters
    ----------
    dpower_dt_W_s : float or array
        Time derivative of the power [W/s].
    delay_s : float
        Delay d of the power reading [s].

    Returns
    -------
    float or array
        Power change [W].

    References
    ----------
    First-order expansion of a dead time (Taylor series in d).
    """
    return -delay_s * dpower_dt_W_s
