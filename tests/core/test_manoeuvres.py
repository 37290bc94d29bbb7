"""Impulsive manoeuvres and gravity assists in the numeric core (orbits.core.manoeuvres.impulsive,
orbits.core.manoeuvres.assist).

References: the vis-viva law evaluated in mpmath at 50 digits (the naive differences, which mpmath can afford),
published values (Wikipedia's Hohmann example, the bi-elliptic thresholds 11.94 and 15.58 of Vallado), the notes'
collision formulas (IX.vii) and identities (energy, period, the third cosmic velocity of orbits.core.encounters.escape).
"""

import math

import mpmath
import mpref
import numpy as np
import pytest

from orbits._common.constants import BODIES, EARTH_MEAN_RADIUS, STANDARD_GRAVITY
from orbits.core.encounters import escape
from orbits.core.encounters.flyby import deflection_angle, impact_parameter
from orbits.core.manoeuvres import assist
from orbits.core.manoeuvres import impulsive as manoeuvres
from orbits.core.mechanics import collisions

MU_EARTH = 398600.4418e9
mp = mpmath.mpf


def ulps(x, ref):
    return float(mpref.ulp_error(x, ref))


def vis_viva(r, a, mu):
    return mpmath.sqrt(mu * (2 / r - 1 / a))


def mp_hohmann(r1, r2, mu):
    r1, r2, mu = mp(r1), mp(r2), mp(mu)
    a = (r1 + r2) / 2
    return vis_viva(r1, a, mu) - mpmath.sqrt(mu / r1), mpmath.sqrt(mu / r2) - vis_viva(r2, a, mu)


RATIOS = [1 + 1e-9, 1 + 1e-5, 1.5, 6.3138, 11.94, 100.0, 1 / 3, 1e-4]


@pytest.mark.parametrize("ratio", RATIOS)
def test_hohmann_burns_within_a_few_ulp_of_mpmath(ratio):
    r1 = 6678e3
    r2 = r1 * ratio
    dv1, dv2 = manoeuvres.hohmann_delta_v(r1, r2, MU_EARTH)
    with mpmath.workdps(50):
        ref1, ref2 = mp_hohmann(r1, r2, MU_EARTH)
        assert ulps(dv1, ref1) <= 4 and ulps(dv2, ref2) <= 4  # measured 1.75 (also 1e-9 apart: no cancellation)
        t_ref = mpmath.pi * mpmath.sqrt(((mp(r1) + mp(r2)) / 2) ** 3 / MU_EARTH)
        assert ulps(manoeuvres.hohmann_time(r1, r2, MU_EARTH), t_ref) <= 4


def test_hohmann_from_leo_to_geo_matches_the_published_example():
    """Wikipedia, "Hohmann transfer orbit", Example: 6678 km (300 km altitude) to 42164 km. Circular speeds 7.73
    and 3.07 km/s, transfer ellipse 10.15 km/s at perigee and 1.61 km/s at apogee, burns 2.42 + 1.46 = 3.88 km/s
    (differences of the rounded speeds), escape from LEO 10.93 - 7.73 = 3.20 km/s. Unrounded: 2.4258 + 1.4668 =
    3.8926 km/s, in 5.275 h."""
    r1, r2 = 6678e3, 42164e3
    speeds = [math.sqrt(MU_EARTH / r1), math.sqrt(MU_EARTH / r2), manoeuvres.apsis_speed(r1, r2, MU_EARTH),
              manoeuvres.apsis_speed(r2, r1, MU_EARTH)]
    assert [round(v / 1e3, 2) for v in speeds] == [7.73, 3.07, 10.15, 1.61]
    dv1, dv2 = manoeuvres.hohmann_delta_v(r1, r2, MU_EARTH)
    assert abs(dv1 / 1e3 - 2.42) < 0.01 and abs(dv2 / 1e3 - 1.46) < 0.01 and abs((dv1 + dv2) / 1e3 - 3.88) < 0.015
    assert round((dv1 + dv2) / 1e3, 3) == 3.893
    assert round(manoeuvres.hohmann_time(r1, r2, MU_EARTH) / 3600, 3) == 5.275
    assert round(manoeuvres.departure_delta_v(r1, 0.0, MU_EARTH) / 1e3, 2) == 3.20


def test_lowering_mirrors_raising():
    up = manoeuvres.hohmann_delta_v(7e6, 4.2e7, MU_EARTH)
    down = manoeuvres.hohmann_delta_v(4.2e7, 7e6, MU_EARTH)
    assert down[0] == -up[1] and down[1] == -up[0]


def mp_bielliptic(r1, r2, rb, mu):
    r1, r2, rb, mu = mp(r1), mp(r2), mp(rb), mp(mu)
    a1, a2 = (r1 + rb) / 2, (r2 + rb) / 2
    return (vis_viva(r1, a1, mu) - mpmath.sqrt(mu / r1), vis_viva(rb, a2, mu) - vis_viva(rb, a1, mu),
            mpmath.sqrt(mu / r2) - vis_viva(r2, a2, mu))


@pytest.mark.parametrize("r2, rb", [(15.0, 30.0), (1 + 1e-9, 2.0), (0.2, 5.0), (50.0, 1e6), (3.0, 3.0 + 1e-6)])
def test_bielliptic_burns_within_a_few_ulp_of_mpmath(r2, rb):
    scale = 7e6
    burns = manoeuvres.bielliptic_delta_v(scale, r2 * scale, rb * scale, MU_EARTH)
    with mpmath.workdps(50):
        refs = mp_bielliptic(scale, r2 * scale, rb * scale, MU_EARTH)
        assert max(ulps(b, ref) for b, ref in zip(burns, refs, strict=True)) <= 6  # measured 1.3


def mp_hohmann_total(ratio):
    """The Hohmann budget from r1 = 1 to r2 = ratio > 1 about mu = 1 (both burns prograde)."""
    return sum(mp_hohmann(1, ratio, 1))


def mp_bielliptic_total(ratio, rb):
    """The bi-elliptic budget from r1 = 1 out to rb >= ratio and down to r2 = ratio (the last burn retrograde),
    smooth in rb through rb = ratio, where it equals Hohmann's."""
    dv1, dv2, dv3 = mp_bielliptic(1, ratio, rb, 1)
    return dv1 + dv2 - dv3


def total(burns):
    return sum(abs(b) for b in burns)


def test_bielliptic_thresholds_11_94_and_15_58():
    """Vallado, Fundamentals of Astrodynamics (4th ed.), sec. 6.3.2, and Wikipedia "Bi-elliptic transfer": the
    bi-elliptic transfer can beat Hohmann for r2 / r1 > 11.94 (with rb far enough) and beats it for every rb > r2
    once r2 / r1 > 15.58. Solved here in mpmath: 11.9387654726 and 15.5817187388."""
    with mpmath.workdps(40):
        # rb -> infinity: dv1 = (sqrt 2 - 1) v1, dv2 -> 0, dv3 = (sqrt 2 - 1) v2
        far = mpmath.findroot(lambda k: mp_hohmann_total(k) - (mpmath.sqrt(2) - 1) * (1 + 1 / mpmath.sqrt(k)),
                              (11.9, 12.0), solver="bisect")
        # every rb wins once the budget falls as rb leaves r2
        every = mpmath.findroot(lambda k: mpmath.diff(lambda rb: mp_bielliptic_total(k, rb), k), (15.5, 15.6),
                                solver="bisect")
    assert round(float(far), 2) == 11.94 and round(float(every), 2) == 15.58
    assert abs(float(far) - 11.9387654726) < 1e-9 and abs(float(every) - 15.5817187388) < 1e-9
    # the float64 core shows the same switches
    for ratio, rb, bi_wins in [(11.90, 1e9, False), (11.98, 1e9, True), (15.50, 15.5 * 1.001, False),
                               (15.66, 15.66 * 1.001, True), (15.66, 40.0, True), (13.0, 13.0 * 1.001, False)]:
        hohmann = total(manoeuvres.hohmann_delta_v(1.0, ratio, 1.0))
        bielliptic = total(manoeuvres.bielliptic_delta_v(1.0, ratio, rb, 1.0))
        assert (bielliptic < hohmann) == bi_wins, (ratio, rb)


def test_plane_changes():
    v = 7546.0
    for angle in (1e-8, 0.1, math.radians(28.5), math.pi):
        single = manoeuvres.plane_change_delta_v(v, angle)
        assert single == pytest.approx(manoeuvres.combined_delta_v(v, v, angle), rel=4e-16)
        with mpmath.workdps(50):
            ref = 2 * mp(v) * mpmath.sin(mp(angle) / 2)
        assert ulps(single, ref) <= 2
    for v1, v2, angle in [(1607.8, 3074.7, math.radians(28.5)), (3074.7, 3074.7 * (1 + 1e-9), 1e-7), (7e3, 1e3, 3.0)]:
        with mpmath.workdps(50):
            ref = mpmath.sqrt(mp(v1) ** 2 + mp(v2) ** 2 - 2 * mp(v1) * mp(v2) * mpmath.cos(mp(angle)))
        assert ulps(manoeuvres.combined_delta_v(v1, v2, angle), ref) <= 4  # law of cosines without cancellation
    assert manoeuvres.combined_delta_v(5.0, 3.0, 0.0) == 2.0


@pytest.mark.parametrize("phase, k", [(0.5, 1), (-0.5, 1), (1e-9, 1), (2.0, 3), (-3.0, 2)])
def test_phasing(phase, k):
    r = 7e6
    a = manoeuvres.phasing_semi_major_axis(r, phase, k)
    period = manoeuvres.phasing_time(r, phase, k, MU_EARTH) / k
    assert period == pytest.approx(2 * math.pi * math.sqrt(a**3 / MU_EARTH), rel=1e-14)  # Kepler III
    # k phasing periods take the chaser round k times while the target, `phase` ahead, goes round k times less phase
    n = math.sqrt(MU_EARTH / r**3)
    assert n * k * period == pytest.approx(2 * math.pi * k - phase, rel=1e-14)
    with mpmath.workdps(50):
        a_ref = mp(r) * (1 - mp(phase) / (2 * mpmath.pi * k)) ** (mp(2) / 3)
        ref = vis_viva(mp(r), a_ref, mp(MU_EARTH)) - mpmath.sqrt(mp(MU_EARTH) / r)
    assert ulps(manoeuvres.phasing_delta_v(r, phase, k, MU_EARTH), ref) <= 8  # measured 1.8, tiny phases too
    assert (manoeuvres.phasing_delta_v(r, phase, k, MU_EARTH) < 0) == (phase > 0)  # catch up by dropping lower


def test_departure_reproduces_the_third_cosmic_velocity():
    """XXI.ix as a burn: from the surface of the notes' Earth (mu = g0 R**2), leaving with the solar escape excess
    (sqrt 2 - 1) v_earth, the speed after the burn is the third cosmic velocity 16.648 km/s (ERRATA #54)."""
    g, radius = STANDARD_GRAVITY, EARTH_MEAN_RADIUS
    v_earth = math.sqrt(BODIES["Sun"].gm / BODIES["Earth"].orbit.a)
    mu = g * radius**2
    v_inf = escape.escape_excess_speed(v_earth)
    burn = manoeuvres.departure_delta_v(radius, v_inf, mu)
    v3 = escape.third_cosmic_velocity(v_earth, escape.second_cosmic_velocity(g, radius))
    assert burn + escape.first_cosmic_velocity(g, radius) == pytest.approx(v3, rel=4e-16)
    assert round(v3 / 1e3, 3) == 16.648


def test_elastic_collision_is_the_notes_ix_vii():
    """IX.vii: v1' = ((m1 - m2) v1 + 2 m2 v2) / (m1 + m2) and v2' likewise (in mpmath); momentum and kinetic
    energy conserved; a massless probe leaves a planet at 2 v1 - v2, exactly. The gravity assist's collision is
    the collisions module's (one home), at e = 1."""
    for m1, m2, v1, v2 in [(3.0, 1.0, 2.0, -5.0), (1.0, 1.0, 4.0, 1.0), (1.9e27, 722.0, 13.06e3, -10e3)]:
        a1, a2 = collisions.velocities_after(m1, v1, m2, v2, 1.0)
        with mpmath.workdps(50):
            M1, M2, V1, V2 = map(mp, (m1, m2, v1, v2))
            ref1 = ((M1 - M2) * V1 + 2 * M2 * V2) / (M1 + M2)
            ref2 = ((M2 - M1) * V2 + 2 * M1 * V1) / (M1 + M2)
        assert abs(a1 - ref1) <= 4e-16 * abs(ref1) + 1e-300 and abs(a2 - ref2) <= 4e-16 * abs(v1 - v2)
        assert m1 * a1 + m2 * a2 == pytest.approx(m1 * v1 + m2 * v2, rel=1e-15)
    assert collisions.velocities_after(1.9e27, 13.06e3, 0.0, -10e3, 1.0) == (13.06e3, 2 * 13.06e3 + 10e3)


def test_assist_turn_and_velocity_change():
    """|v_out - v_in| = 2 v_inf sin(delta / 2) = 2 v_inf / (1 + r_p v_inf**2 / mu); the probe's heliocentric energy
    changes by V . dv; |v_inf| is kept."""
    mu, rp, v_inf = BODIES["Jupiter"].gm, 2e8, np.array([-13.06e3, 7.4e3, 0.0])
    speed = np.linalg.norm(v_inf)
    delta = deflection_angle(impact_parameter(rp, speed, mu), speed, mu)
    planet = np.array([13.06e3, 0.0, 0.0])
    v_in = planet + v_inf
    v_out = assist.outgoing_velocity(v_in, planet, [0.0, 0.0, 1.0], delta)
    assert np.linalg.norm(v_out - planet) == pytest.approx(speed, rel=1e-15)
    assert np.linalg.norm(v_out - v_in) == pytest.approx(assist.delta_v_magnitude(speed, rp, mu), rel=1e-15)
    assert 0.5 * (v_out @ v_out - v_in @ v_in) == pytest.approx(planet @ (v_out - v_in), rel=1e-13)
    # the turn is counterclockwise about the normal: the excess velocity's angular position grows by delta
    turned = math.atan2(*(v_out - planet)[1::-1]) - math.atan2(*v_inf[1::-1])
    assert math.remainder(turned - delta, 2 * math.pi) == pytest.approx(0.0, abs=1e-15)
    # only the normal's part perpendicular to v_inf counts
    tilted = assist.turn(v_inf, np.array([0.0, 0.0, 2.0]) + 3.0 * v_inf / speed, delta)
    assert np.allclose(tilted, assist.turn(v_inf, [0.0, 0.0, 1.0], delta), rtol=1e-15, atol=1e-11)


def test_impulse_plans_hold_the_closed_forms():
    plan = manoeuvres.hohmann_plan(7e6, 4.2e7, MU_EARTH)
    assert np.linalg.norm(plan.delta_v, axis=1).sum() == pytest.approx(
        total(manoeuvres.hohmann_delta_v(7e6, 4.2e7, MU_EARTH)), rel=1e-15)
    plan = manoeuvres.bielliptic_plan(7e6, 1.05e8, 2.1e8, MU_EARTH)
    assert plan.times[-1] == pytest.approx(manoeuvres.bielliptic_time(7e6, 1.05e8, 2.1e8, MU_EARTH), rel=1e-15)
    plan = manoeuvres.phasing_plan(7e6, 0.3, 2, MU_EARTH, coast=100.0)
    assert np.linalg.norm(plan.final_r) == pytest.approx(7e6, rel=1e-15) and plan.duration == plan.times[-1] + 100.0
