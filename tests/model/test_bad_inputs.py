"""Bad input values and unreadable files refused in one InputError naming the field (issue 12).

Physical ranges of the friction law, the duty cycle, the oil, the motor and the geometry;
the sample cap checked before anything is allocated; input files that cannot be read
(a directory, EIO, permission, not UTF-8, too large) named with the reason and never
with their content; the evaluation's guard against a non-finite loss; the synthetic
rig's seed and strengths; the smoothing fit that identifies nothing.
"""

import errno
import math
from dataclasses import replace
from types import SimpleNamespace

import numpy as np
import pytest

from oilgap.model import duty_cycle as dc_module
from oilgap.model.duty_cycle import MAX_SAMPLES, DutyCycle
from oilgap.model.errors import InputError, SolverError
from oilgap.model.evaluation import evaluate_case
from oilgap.model.fluid_table import read_fluid_table
from oilgap.model.io import inputs
from oilgap.model.io.case_io import case_from_dict, read_case_toml, seed_case
from oilgap.model.io.case_write import case_to_dict
from oilgap.model.io.inputs import read_input_text
from oilgap.model.motor import motor_torque
from oilgap.model.oils import Oil, read_oils_csv
from oilgap.model.skin_friction import FrictionLaw, check_friction_ranges
from oilgap.studies.rigs.synth import SynthConfig, synthesize
from oilgap.studies.smoothing.fit import _refuse_unidentified, fit_smoothing

SECRET = "root:x:0:0:hunter2-secret"


def seed_doc() -> dict:
    return case_to_dict(seed_case())


def changed(table: str, **keys) -> dict:
    doc = seed_doc()
    doc["region1"].pop("T1_unfilled_mm")   # unfilled grooves: follow T1 and T4
    doc["region1"].pop("T4_unfilled_mm")
    doc.setdefault(table, {}).update(keys)
    return doc


# --------------------------------------------------------------------------- friction


@pytest.mark.parametrize("key,value", [
    ("gamma", 1e300), ("gamma", -0.5), ("gamma", 3.5), ("beta", 1000.0), ("beta", -2.0),
    ("C", 1e9), ("alpha", 10.0), ("scale", 1e6), ("scale", 1e-4),
])
def test_friction_number_outside_its_range_is_refused(key, value):
    with pytest.raises(InputError) as e:
        case_from_dict(changed("friction", **{key: value}))
    assert e.value.field == key and "allowed range" in str(e.value)


def test_friction_ranges_hold_the_published_laws():
    # Eq. 6 as published, each of its branches as a power law, the seed's fitted gamma
    check_friction_ranges(FrictionLaw(gamma=0.566))
    for C, beta in ((10.0, -1.0), (2.0, -0.6), (1.03, -0.5), (0.065, -0.2)):
        check_friction_ranges(FrictionLaw(form="power-law", C=C, beta=beta, gamma=0.98))


# --------------------------------------------------------------------------- duty cycle


def test_sample_cap_is_checked_before_anything_is_allocated(monkeypatch):
    def no_alloc(*a, **k):
        raise AssertionError("allocated before the sample count was checked")
    monkeypatch.setattr(dc_module.np, "arange", no_alloc)
    with pytest.raises(InputError) as e:
        DutyCycle.sine(duration_s=1e9, sample_interval_s=0.001)
    assert e.value.field == "duration_s" and "1e+12 samples" in str(e.value)
    with pytest.raises(InputError) as e:   # the ratio overflows to inf
        DutyCycle.sine(duration_s=1e300, sample_interval_s=1e-300)
    assert e.value.field == "duration_s"


def test_sample_cap_allows_a_day_every_10_ms():
    assert 86400 / 0.01 <= MAX_SAMPLES


@pytest.mark.parametrize("kw,field", [
    ({"peak_speed_rpm": 1e300}, "peak_speed_rpm"),
    ({"peak_speed_rpm": 2e5}, "peak_speed_rpm"),
    ({"frequency_hz": 2.5, "sample_interval_s": 0.2}, "frequency_hz"),   # Nyquist is 2.5 Hz
    ({"frequency_hz": 5.0, "duration_s": 10.0}, "frequency_hz"),  # 5 Hz sampled every 0.2 s
])
def test_bad_sine_refused(kw, field):
    with pytest.raises(InputError) as e:
        DutyCycle.sine(**kw)
    assert e.value.field == field


@pytest.mark.parametrize("text,field", [
    ("time_s,speed_rpm\n0,0\n1,0\n", "speed_rpm"),              # never turns
    ("time_s,speed_rpm\n0,1e6\n1,0\n", "speed_rpm"),            # 1e6 rpm
    ("time_s,speed_rpm\n0,-1e300\n1,0\n", "speed_rpm"),
])
def test_bad_duty_cycle_csv_values(tmp_path, text, field):
    p = tmp_path / "cyc.csv"
    p.write_text(text)
    with pytest.raises(InputError) as e:
        DutyCycle.from_csv(p)
    assert e.value.field == field


def test_duty_cycle_csv_longer_than_the_cap(tmp_path, monkeypatch):
    monkeypatch.setattr(dc_module, "MAX_SAMPLES", 3)
    p = tmp_path / "cyc.csv"
    p.write_text("time_s,speed_rpm\n0,1\n1,2\n2,3\n3,4\n")
    with pytest.raises(InputError) as e:
        DutyCycle.from_csv(p)
    assert e.value.field == "rows"


def test_duty_cycle_csv_with_a_bom_is_read(tmp_path):
    p = tmp_path / "cyc.csv"
    p.write_bytes(b"\xef\xbb\xbftime_s,speed_rpm\n0,10\n1,20\n")
    assert DutyCycle.from_csv(p).peak_omega_rad_s == pytest.approx(20 * math.pi / 30)


# --------------------------------------------------------------------------- input files


def test_unreadable_inputs_name_the_file_and_the_reason(tmp_path, monkeypatch):
    with pytest.raises(InputError, match="is a directory"):
        read_input_text(tmp_path, "case", "TOML file")
    with pytest.raises(InputError, match="no such file"):
        read_input_text(tmp_path / "nope.toml", "case")
    with pytest.raises(InputError, match="not a regular file"):
        read_input_text("/dev/null", "case")
    big = tmp_path / "big.csv"
    big.write_text("x" * 100)
    with pytest.raises(InputError, match="MiB"):
        read_input_text(big, "oils", max_bytes=10)
    bad = tmp_path / "latin1.csv"
    bad.write_bytes("oil,nu40_cSt\nM\xfcller,22\n".encode("latin-1"))
    with pytest.raises(InputError, match="not UTF-8 text .* line 2"):
        read_input_text(bad, "oils")
    for err, words in ((errno.EIO, "input/output error"), (errno.EACCES, "permission denied")):
        def fail(*a, _err=err, **k):
            raise OSError(_err, "boom")
        monkeypatch.setattr(inputs, "open", fail, raising=False)
        with pytest.raises(InputError) as e:
            read_input_text(big, "duty_cycle.csv")
        assert e.value.field == "duty_cycle.csv" and words in str(e.value)
        assert str(big) in str(e.value)
        monkeypatch.undo()


@pytest.mark.parametrize("reader", [
    read_oils_csv, DutyCycle.from_csv, read_fluid_table])
def test_a_file_that_is_not_the_table_is_never_echoed(tmp_path, reader):
    p = tmp_path / "passwd"
    p.write_text(SECRET + "\ndaemon:x:1:1:other-secret\n")
    with pytest.raises(InputError) as e:
        reader(p)
    assert "hunter2" not in str(e.value) and "root:x" not in str(e.value)
    assert e.value.field == "columns" and str(p) in str(e.value)


def test_unknown_column_named_by_position_not_by_text(tmp_path):
    p = tmp_path / "oils.csv"
    p.write_text("oil,nu40_cSt,nu100_cSt,density_kg_m3,hunter2\nX,22,4.5,860,1\n")
    with pytest.raises(InputError) as e:
        read_oils_csv(p)
    assert "hunter2" not in str(e.value) and "#5" in str(e.value)


def test_case_file_that_is_not_a_case_is_not_echoed(tmp_path):
    p = tmp_path / "secrets.toml"
    p.write_text('[database]\npassword = "hunter2"\n')
    with pytest.raises(InputError) as e:
        read_case_toml(p)
    assert "hunter2" not in str(e.value) and e.value.field == "database"


def test_a_long_bad_cell_is_cut_short(tmp_path):
    p = tmp_path / "oils.csv"
    p.write_text("oil,nu40_cSt,nu100_cSt,density_kg_m3\nX," + "z" * 5000 + ",4.5,860\n")
    with pytest.raises(InputError) as e:
        read_oils_csv(p)
    assert e.value.field == "nu40_cSt" and len(str(e.value)) < 300


# --------------------------------------------------------------------------- oils


@pytest.mark.parametrize("nu40,nu100,rho,barus,field", [
    (0.2, 0.1, 850.0, 1.7e-8, "nu40_cSt"),      # Walther: log10(0.9) < 0
    (10.0, 0.3, 850.0, 1.7e-8, "nu100_cSt"),    # log10(1.0) = 0: log of 0
    (10.0, 3.0, 0.001, 1.7e-8, "density_kg_m3"),
    (10.0, 3.0, 8500.0, 1.7e-8, "density_kg_m3"),
    (10.0, 3.0, 850.0, 1.7e-5, "barus_1_GPa"),
])
def test_impossible_oil_refused(nu40, nu100, rho, barus, field):
    with pytest.raises(InputError) as e:
        Oil("thin", nu40, nu100, rho, barus)
    assert e.value.field == field


@pytest.mark.parametrize("key,value", [
    ("molar_mass_kg_per_mol", 1e300), ("sutherland_mu_ref_Pa_s", 1e300),
    ("sutherland_S_K", -110.0), ("sutherland_T_ref_K", 1e6),
])
def test_impossible_gas_refused(key, value):
    gas = {"kind": "gas", "name": "heavy", "molar_mass_kg_per_mol": 0.04,
           "sutherland_mu_ref_Pa_s": 2e-5, "sutherland_T_ref_K": 273.0, "sutherland_S_K": 110.0}
    doc = seed_doc()
    doc["oil"] = dict(gas, **{key: value})
    with pytest.raises(InputError) as e:
        case_from_dict(doc)
    assert e.value.field == key


def test_thinnest_allowed_oil_has_a_finite_state():
    # just above the Walther limit: nu stays finite and above 0.3 cSt at every temperature
    oil = Oil("thin", 0.31, 0.305, 700.0)
    for t in (-60.0, 2.0, 300.0):
        nu = oil.kinematic_viscosity_cSt(t, 11000.0)
        assert math.isfinite(nu) and nu > 0.3


# --------------------------------------------------------------------------- motor, geometry


@pytest.mark.parametrize("table,keys,field", [
    ("motor", {"slot_count": 100000, "slot_opening_mm": 1e6}, "slot_count"),
    ("motor", {"slot_opening_mm": 1e6}, "slot_opening_mm"),
    ("motor", {"slot_count": 1000, "slot_opening_mm": 1.0}, "slot_opening_mm"),  # pitch 0.17
    ("motor", {"remanence_T": 5.0}, "remanence_T"),
    ("motor", {"winding_factor": 1.5}, "winding_factor"),
    ("motor", {"saturation_factor": 0.5}, "saturation_factor"),
    ("motor", {"recoil_permeability": 0.2}, "recoil_permeability"),
    ("motor", {"rotor_density_kg_m3": 1e6}, "rotor_density_kg_m3"),
    ("motor", {"shaft_bore_radius_mm": 24.0}, "shaft_bore_radius_mm"),
    ("region1", {"T3_mm": 1e6, "T4_mm": 1.1e6}, "T3_mm"),           # a 1 km gap
    ("region1", {"T3_mm": 60.0, "T4_mm": 61.0}, "T3_mm"),           # gap 34.6 > R 25.4
    ("region1", {"T3_mm": 25.4000001, "T4_mm": 25.4000001}, "T3_mm"),  # 0.1 um gap
    ("region1", {"length_mm": 1e7}, "length_mm"),
    ("region2", {"gap_mm": 30.0}, "gap_mm"),                        # gap > radius 22
    ("region2", {"radius_mm": 3000.0}, "radius_mm"),
    ("bounds", {"gap_max_mm": 30.0}, "gap_max_mm"),                 # > radius_min 22
])
def test_impossible_joint_refused(table, keys, field):
    with pytest.raises(InputError) as e:
        case_from_dict(changed(table, **keys))
    assert e.value.field == field


def test_seed_motor_is_plausible_by_its_own_numbers():
    # k_C = t/(t - gamma g) >= 1 and B_g = B_r h/(h + mu k_C g) < B_r, by hand
    case = seed_case()
    m, r1 = case.motor, case.region1
    t = 2 * math.pi * r1.T3 / m.slot_count
    u = m.slot_opening / (2 * r1.gap)
    gam = 4 / math.pi * (u * math.atan(u) - 0.5 * math.log(1 + u * u))
    kc = t / (t - gam * r1.gap)
    bg = m.remanence_T * m.magnet_thickness / (m.magnet_thickness
                                               + m.recoil_permeability * kc * r1.gap)
    _, bg_code, kc_code = motor_torque(m, r1.T2, r1.gap, r1.length)
    assert kc_code == pytest.approx(kc, rel=1e-12) and kc > 1.0
    assert bg_code == pytest.approx(bg, rel=1e-12) and bg < m.remanence_T


# --------------------------------------------------------------------------- evaluation guard


def test_non_finite_c_m_is_refused_naming_the_friction_law():
    case = replace(seed_case(), friction=FrictionLaw(form="power-law", beta=1000.0))
    with pytest.raises(InputError) as e:
        evaluate_case(case, thermal="none")
    assert e.value.field == "friction" and "beta = 1000" in str(e.value)


def test_overflow_is_a_solver_failure_not_a_traceback():
    case = replace(seed_case(), friction=FrictionLaw(gamma=1e300))   # 4.0 ** 1e300
    with pytest.raises(SolverError, match="overflowed"):
        evaluate_case(case, thermal="none")


def test_non_finite_oil_state_is_refused_naming_the_oil(monkeypatch):
    def nan_state(self, temp_K, pressure_gauge_Pa=0.0):
        return np.nan, np.nan, 850.0
    monkeypatch.setattr(Oil, "properties", nan_state)
    with pytest.raises(InputError) as e:
        evaluate_case(seed_case(), thermal="none")
    assert e.value.field == "oil" and "VG22" in str(e.value)


# --------------------------------------------------------------------------- synth, smoothing


def test_synth_strength_sign_and_size():
    with pytest.raises(InputError) as e:
        SynthConfig(effect="seal_coulomb_friction", strength=-1.0).resolved()
    assert e.value.field == "strength" and ">= 0" in str(e.value)
    with pytest.raises(InputError):
        SynthConfig(effects={"sensor_delay": -0.1}).resolved()
    with pytest.raises(InputError, match="at most"):
        SynthConfig(effect="seal_coulomb_friction", strength=1e300).resolved()
    # the thermal lag may lead as well as lag: either sign is physical
    assert SynthConfig(effect="thermal_lag", strength=-1.0).resolved().strength == -1.0


def test_synth_negative_seed_refused_before_simulating(monkeypatch):
    monkeypatch.setattr("oilgap.studies.rigs.synth.simulate_truth",
                        lambda *a: pytest.fail("simulated before the seed was checked"))
    with pytest.raises(InputError) as e:
        synthesize(seed=-1)
    assert e.value.field == "seed"


def test_smoothing_resistance_out_of_range_refused():
    with pytest.raises(InputError) as e:
        fit_smoothing("per-oil", 1e6)
    assert "--r-th-k-per-w" in e.value.field


def test_unidentified_smoothing_fit_is_a_failure():
    x = np.array([3.0, 40.0, 40.0, 40.0, 40.0])
    with pytest.raises(SolverError, match="no standard error"):
        _refuse_unidentified("per-oil", "none", SimpleNamespace(x=x, active_mask=np.zeros(5)),
                             np.array([np.nan, 1.0, 1.0, 1.0, 1.0]), 1e3)
    with pytest.raises(SolverError, match="bounds of gamma, T_base"):
        _refuse_unidentified("per-oil", "none",
                             SimpleNamespace(x=x, active_mask=np.array([1, 0, -1, 0, 0])),
                             np.ones(5), 0.5)
    # the shared fit reports R_th at its bound 0 as such: not a failure
    _refuse_unidentified("shared", "none", SimpleNamespace(x=np.array([0.6, 30.0, 0.0]),
                                                           active_mask=np.array([0, 0, -1])),
                         np.ones(3), 0.0)
