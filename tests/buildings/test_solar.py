"""Solar potential: sun positions against published values, the ESRA clear-sky model, annual
irradiation on tilted roofs against PVGIS's clear-sky figures, and shading of a roof by a tower."""

from __future__ import annotations

import datetime as dt
import math

import numpy as np
import pytest

from workstation.buildings.solar import (SolarParams, build_dsm, esra_clear_sky, horizon_angles, plane_irradiation,
                                         sun_position, year_of_sun)


def _t(*args):
    return np.array([dt.datetime(*args, tzinfo=dt.timezone.utc).timestamp()])


def test_sun_position_against_the_spa_example():
    """Reda & Andreas (2004), NREL/TP-560-34302, table A5.1: zenith 50.11162, azimuth 194.34024."""
    z, a = sun_position(_t(2003, 10, 17, 19, 30, 30), 39.742476, -105.1786, 820.0, 11.0)
    assert z[0] == pytest.approx(50.11162, abs=0.02)
    assert a[0] == pytest.approx(194.34024, abs=0.02)


@pytest.mark.parametrize("when,declination", [((2025, 6, 21, 2, 42), 23.436), ((2025, 12, 21, 15, 3), -23.436),
                                              ((2025, 3, 20, 9, 1), 0.0), ((2025, 9, 22, 18, 19), 0.0)])
def test_declination_at_solstices_and_equinoxes(when, declination):
    """At the pole the zenith is 90 minus the declination; the USNO gives the instants of the
    2025 solstices and equinoxes, when the declination is +-obliquity (23.436) or zero."""
    z, _ = sun_position(_t(*when), 90.0, 0.0, refraction=False)
    assert 90.0 - z[0] == pytest.approx(declination, abs=0.01)


def test_daily_extraterrestrial_irradiation_matches_the_closed_form():
    """Integrated G0 cos(zenith) over a day equals Duffie & Beckman (2013) eq. 1.10.3."""
    lat, day = 48.0, 172
    t0 = dt.datetime(2025, 6, 21, tzinfo=dt.timezone.utc).timestamp()
    t = t0 + np.arange(0, 86400, 60.0) + 30.0
    z, _ = sun_position(t, lat, 0.0, refraction=False)
    g0 = 1367.0 * (1 + 0.033 * math.cos(2 * math.pi * day / 365))
    h_num = np.sum(g0 * np.maximum(np.cos(np.radians(z)), 0)) * 60.0
    zn, _ = sun_position(np.array([t0 + 12 * 3600.0]), 90.0, 0.0, refraction=False)
    dec = math.radians(90.0 - zn[0])
    phi = math.radians(lat)
    ws = math.acos(-math.tan(phi) * math.tan(dec))
    h_ref = 86400 * g0 / math.pi * (math.cos(phi) * math.cos(dec) * math.sin(ws) + ws * math.sin(phi) * math.sin(dec))
    assert h_num == pytest.approx(h_ref, rel=0.003)


def test_esra_beam_at_the_zenith():
    """m = 1 and TL = 1: B = G0 exp(-0.8662 dR(1)) with dR(1) = 1 / 8.26713 (Kasten 1996)."""
    beam, diff = esra_clear_sky(np.array([90.0]), np.array([81]), 1.0)
    g0 = 1367.0 * (1 + 0.03344 * math.cos(2 * math.pi * 81 / 365.25 - 0.048869))
    assert beam[0] == pytest.approx(g0 * math.exp(-0.8662 / 8.26713), rel=2e-3)
    b3, d3 = esra_clear_sky(np.array([30.0]), np.array([81]), 3.0)
    b5, d5 = esra_clear_sky(np.array([30.0]), np.array([81]), 5.0)
    assert b5[0] < b3[0] and d5[0] > d3[0]  # turbidity moves beam into diffuse


def _normal(tilt, azimuth):
    t, a = math.radians(tilt), math.radians(azimuth)
    return np.array([math.sin(t) * math.sin(a), math.sin(t) * math.cos(a), math.cos(t)])


def test_annual_irradiation_of_tilted_roofs_at_48_north():
    p = SolarParams(latitude=48.0, longitude=11.0)
    h, south, north, east = plane_irradiation(np.array([_normal(0, 0), _normal(35, 180), _normal(35, 0), _normal(35, 90)]), None, p)
    assert 1500 < h < 2100  # clear-sky horizontal, kWh/m2/year
    assert 1.15 < south / h < 1.30  # the optimal tilt gains about a fifth under clear skies
    assert north < east < h < south


def test_a_tower_south_of_a_roof_shades_it():
    """A flat roof 10 m up with a 40 m tower 8 m to its south loses much of its beam; the same
    tower to the north costs it only diffuse light."""
    g = np.stack(np.meshgrid(np.arange(0, 60, 0.5), np.arange(0, 60, 0.5)), -1).reshape(-1, 2)
    z = np.full(len(g), 10.0)
    roof = np.array([[30.0, 30.0, 10.2]])
    p = SolarParams(latitude=48.0, longitude=0.0, step_minutes=60.0)
    n = np.array([[0.0, 0.0, 1.0]])
    out = {}
    for name, y in (("south", 22.0), ("north", 38.0)):
        zz = np.where((np.abs(g[:, 0] - 30) < 3) & (np.abs(g[:, 1] - y) < 3), 50.0, z)
        dsm, origin = build_dsm(np.column_stack([g, zz]), 0.5)
        hor = horizon_angles(dsm, origin, 0.5, roof, 36, 100.0)
        out[name] = plane_irradiation(n, hor, p)[0]
    free = plane_irradiation(n, np.zeros((1, 36)), p)[0]
    assert out["south"] < 0.7 * free
    assert 0.9 * free < out["north"] < free


# PVGIS 5 (European Commission, Joint Research Centre), tool "Daily radiation" (DRcalc): the
# clear-sky global irradiance on a fixed plane, Gcs(i), of the mean day of each month at
# 51.640 N 0.510 W (87 m), slope 35 degrees, azimuth 0 (south), radiation database PVGIS-SARAH
# 2005-2016, horizon from the DEM. The outputs are archived as
# Dailydata_51.640_-0.510_SA_<month>_35deg_0deg.json in the public repository
# github.com/michaelstreeter101/solar_farm (commit 488f621296eafc28445fdc2884c21199a33beb2a).
# Below: the sum of each month's 24 hourly values (W/m^2 x 1 h), i.e. that month's mean daily
# clear-sky in-plane irradiation in Wh/m^2/day. PVGIS's clear-sky model is ESRA (Rigollier et al.
# 2000) with a monthly Linke turbidity climatology; ours uses one TL for the whole year.
PVGIS_CLEAR_SKY_35S_51N_WH_DAY = np.array([3466.9, 4653.6, 5922.0, 7478.1, 8009.3, 7943.6,
                                           7719.2, 7326.4, 6288.9, 5109.6, 3672.1, 2927.6])
DAYS = np.array([31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31])


def test_clear_sky_annual_irradiation_of_a_35_degree_south_roof_against_pvgis():
    """The goal's quantity, the clear-sky annual irradiation on an unshaded south-facing 35-degree
    plane, against the same quantity from PVGIS (2,147 kWh/m^2/year at 51.64 N): within 5 %
    with the default TL (3.5, not chosen on these figures), and the months in the same
    proportions. 51.64 N is the latitude PVGIS's clear-sky output is available for here; the
    goal's 48 N is checked for plausibility in test_annual_irradiation_of_tilted_roofs_at_48_north."""
    p = SolarParams(latitude=51.64, longitude=-0.51, elevation=87.0)
    n = _normal(35, 180)[None, :]
    pvgis_year = float(PVGIS_CLEAR_SKY_35S_51N_WH_DAY @ DAYS) / 1000.0
    ours = plane_irradiation(n, None, p)[0]
    assert pvgis_year == pytest.approx(2146.7, abs=0.1)
    assert ours == pytest.approx(pvgis_year, rel=0.05)
    zen, az, doy, hours = year_of_sun(p)
    month = np.searchsorted(np.cumsum(DAYS), doy, side="left")  # 0-11
    monthly = np.array([plane_irradiation(n, None, p, sun=(zen[month == m], az[month == m], doy[month == m], hours))[0]
                        for m in range(12)])
    assert monthly.sum() == pytest.approx(ours, rel=1e-9)
    assert np.corrcoef(monthly, PVGIS_CLEAR_SKY_35S_51N_WH_DAY * DAYS / 1000.0)[0, 1] > 0.99
