"""`ws plan-flight`: swath, spacing, density, lines and time of an ALS/ULS block, or its inverse."""

from __future__ import annotations

import click

from workstation.lidar.planning import SOLVABLE, FlightParams, solve_for_density
from workstation.lidar.scanners import AIRBORNE_KINDS

from .options import emit_json
from .options import FiniteFloatRange, nonneg_float, positive_float
from .options import RegistryChoice, bound, field_option, param_group


@click.command("plan-flight")
@param_group(
    "given",
    bound(FlightParams, "altitude", "--altitude", type=positive_float, show_default=True,
          help="Flying height above ground in metres."),
    bound(FlightParams, "speed", "--speed", type=positive_float, show_default=True, help="Ground speed in m/s."),
    bound(FlightParams, "prf", "--prf", type=positive_float, show_default=True, help="Pulse repetition frequency in Hz."),
    bound(FlightParams, "scan_frequency", "--scan-rate", "--scan-frequency", "scan_rate", type=positive_float,
          show_default=True,
          help="Scan frequency in Hz (mirror cycles for zigzag, lines for polygon, revolutions for palmer)."),
    bound(FlightParams, "fov_deg", "--fov", type=FiniteFloatRange(0.0, 180.0, min_open=True, max_open=True),
          show_default=True, help="Full field of view in degrees."),
    bound(FlightParams, "overlap", "--overlap", type=FiniteFloatRange(0.0, 1.0, max_open=True), show_default=True,
          help="Lateral strip overlap as a fraction 0-1."),
    bound(FlightParams, "area_width", "--area-width", type=positive_float, show_default=True,
          help="Block width across the lines in metres."),
    bound(FlightParams, "area_length", "--area-length", type=positive_float, show_default=True,
          help="Block length along the lines in metres."),
    bound(FlightParams, "run_in", "--run-in", type=nonneg_float, show_default=True,
          help="Extra line length before and after the block in metres."),
    bound(FlightParams, "bank_deg", "--bank", type=FiniteFloatRange(0.0, 90.0, min_open=True, max_open=True),
          show_default=True, help="Bank angle in turns in degrees."),
    bound(FlightParams, "pattern", "--pattern", type=RegistryChoice(AIRBORNE_KINDS), show_default=True,
          help="Scan mechanism."),
)
@click.option("--divergence", type=nonneg_float, default=None, help="Beam divergence in mrad (adds the footprint diameter).")
@click.option("--target-density", type=positive_float, default=None,
              help="Solve for this point density in points/m^2 per pass (inverse problem).")
@field_option(solve_for_density, "solve", "--solve-for", type=RegistryChoice(SOLVABLE), show_default=True,
              help="Which parameter --target-density solves for.")
@click.option("--json", "as_json", is_flag=True, help="Print the plan as JSON on stdout (SI units).")
def plan_flight(given, divergence, target_density, solve_for, as_json):
    """Plan an airborne LiDAR block: swath width, along/across spacing, density, NPS, lines, time.

    With --target-density, first solve for the PRF (or speed, or altitude) that reaches it.
    """
    from workstation.lidar.planning import plan_flight as plan

    p = FlightParams(**given)
    if target_density is not None:
        p = solve_for_density(target_density, p, solve_for)
    result = plan(p, divergence)
    d = result.to_dict()
    if target_density is not None:
        d["solved_for"] = solve_for
        d["solved_value"] = getattr(p, solve_for)
    if as_json:
        emit_json(d)
        return
    rows = [
        ("altitude", f"{p.altitude:.1f} m"), ("speed", f"{p.speed:.2f} m/s"), ("prf", f"{p.prf:.0f} Hz"),
        ("swath width", f"{result.swath_width:.1f} m"), ("spacing along", f"{result.spacing_along:.3f} m"),
        ("spacing across", f"{result.spacing_across:.3f} m"), ("density (per pass)", f"{result.density:.2f} pts/m²"),
        ("density (block mean)", f"{result.density_block:.2f} pts/m²"), ("NPS", f"{result.nps:.3f} m"),
        ("flight lines", f"{result.flight_lines} (spacing {result.line_spacing:.1f} m)"),
        ("turn", f"radius {result.turn_radius:.0f} m, {result.turn_time_s:.0f} s"),
        ("total time", f"{result.total_time_s:.0f} s ({result.total_time_s / 60:.1f} min)"),
        ("max PRF, one pulse in air", f"{result.max_prf_one_pulse_in_air:.0f} Hz"),
        ("pulses in the air", f"{result.pulses_in_air}" + (" (needs an MPiA sensor)" if result.pulses_in_air > 1 else "")),
    ]
    if result.footprint_diameter is not None:
        rows.append(("footprint", f"{result.footprint_diameter:.3f} m"))
    if target_density is not None:
        rows.insert(0, ("solved", f"{solve_for} for {target_density} pts/m²"))
    w = max(len(k) for k, _ in rows)
    for k, v in rows:
        click.echo(f"{k:<{w}}  {v}")
