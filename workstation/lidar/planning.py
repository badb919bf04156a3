r"""ALS / ULS flight planning: swath, spacing, density, lines, time; and the inverse problem.

Relations for a scanner on a platform flying at height :math:`H` above flat ground with
ground speed :math:`v`, pulse rate :math:`F` (PRF), full field of view :math:`\theta` and
:math:`f_l` scan lines per second (Baltsavias 1999, Table 3 and eqs. 8-20):

* swath width :math:`B = 2 H \tan(\theta/2)`;
* along-track spacing of scan lines :math:`\Delta_a = v / f_l` (zigzag: the mean, the spacing
  goes from 0 at the swath edge to :math:`2 v / f_l` for an oscillating mirror);
* across-track spacing :math:`\Delta_c = B f_l / F` (points per line :math:`F / f_l`);
* point density :math:`\rho = F / (B v) = 1 / (\Delta_a \Delta_c)` per pass, and
  :math:`\rho / (1 - q)` on average over the block with lateral overlap :math:`q`;
* nominal point spacing :math:`\mathrm{NPS} = 1/\sqrt{\rho}` (ASPRS Positional Accuracy
  Standards 2014);
* lines over a block of width :math:`W`: spacing :math:`d = B(1-q)`,
  :math:`n = \lceil (W - B)/d \rceil + 1`;
* total time :math:`T = n (L + 2 L_{run}) / v + (n - 1) T_{turn}` with the turn of
  :func:`workstation.lidar.platforms.turn_length` at bank angle :math:`\varphi`
  (:math:`R = v^2 / (g \tan\varphi)`);
* one pulse in the air (no multiple-pulses-in-air ambiguity): :math:`F \le c / (2 R_{max})`
  with the slant range at the swath edge :math:`R_{max} = H / \cos(\theta/2)`; above that
  ``pulses_in_air`` = :math:`\lceil 2 F R_{max} / c \rceil` pulses are in flight at once.

The inverse: with a target density :math:`\rho` and two of :math:`H, v, F` fixed, the third
follows from :math:`\rho = F / (2 H \tan(\theta/2)\, v)`.

References
----------
E. P. Baltsavias (1999). Airborne laser scanning: basic relations and formulas. ISPRS J.
Photogramm. Remote Sens. 54(2-3):199-214.
ASPRS (2015). ASPRS Positional Accuracy Standards for Digital Geospatial Data, Ed. 1.
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass

from workstation.core.errors import InvalidInputError

from .platforms import G, turn_length

C_LIGHT = 299_792_458.0  # m/s
LINES_PER_CYCLE = {"zigzag": 2.0, "polygon": 1.0, "palmer": 2.0, "rotating": 1.0}


@dataclass(frozen=True)
class FlightParams:
    """Inputs of a flight plan.

    Attributes
    ----------
    altitude : float
        Flying height above ground (m).
    speed : float
        Ground speed (m/s).
    prf : float
        Pulse repetition frequency (Hz).
    scan_frequency : float
        Scan frequency (Hz): mirror cycles (zigzag, 2 lines each), lines (polygon) or
        revolutions (palmer).
    fov_deg : float
        Full field of view across track (degrees).
    overlap : float
        Lateral overlap between neighbouring strips (0-1).
    area_width, area_length : float
        Block size across and along the flight direction (m).
    run_in : float
        Extra line length flown before and after the block (m).
    bank_deg : float
        Bank angle in the turns (degrees).
    pattern : str
        ``zigzag``, ``polygon`` or ``palmer``.
    """

    altitude: float = 1000.0
    speed: float = 60.0
    prf: float = 300_000.0
    scan_frequency: float = 50.0
    fov_deg: float = 40.0
    overlap: float = 0.3
    area_width: float = 2000.0
    area_length: float = 3000.0
    run_in: float = 500.0
    bank_deg: float = 20.0
    pattern: str = "zigzag"

    def __post_init__(self):
        for name in ("altitude", "speed", "prf", "scan_frequency", "area_width", "area_length"):
            v = getattr(self, name)
            if not (isinstance(v, (int, float)) and v > 0 and math.isfinite(v)):
                raise InvalidInputError(f"{name} must be a positive number, got {v}", field=name)
        if not 0 < self.fov_deg < 180:
            raise InvalidInputError(f"fov {self.fov_deg} must be in (0, 180) degrees", field="fov_deg")
        if not 0 <= self.overlap < 1:
            raise InvalidInputError(f"overlap {self.overlap} must be in [0, 1)", field="overlap")
        if not 0 < self.bank_deg < 60:
            raise InvalidInputError(f"bank angle {self.bank_deg} must be in (0, 60) degrees", field="bank_deg")
        if self.pattern not in LINES_PER_CYCLE:
            raise InvalidInputError(f"unknown pattern '{self.pattern}'", "zigzag, polygon or palmer", field="pattern")


@dataclass(frozen=True)
class FlightPlan:
    """Outputs of a flight plan (SI units: m, s, points/m^2)."""

    swath_width: float
    spacing_along: float
    spacing_across: float
    density: float
    density_block: float
    nps: float
    flight_lines: int
    line_spacing: float
    line_length: float
    turn_radius: float
    turn_time_s: float
    total_time_s: float
    max_prf_one_pulse_in_air: float
    pulses_in_air: int
    footprint_diameter: float | None
    params: dict

    def to_dict(self) -> dict:
        return asdict(self)


def plan_flight(p: FlightParams, divergence_mrad: float | None = None) -> FlightPlan:
    """Swath, spacings, density, NPS, lines and time of a flight block (see module docs).

    Examples
    --------
    >>> plan = plan_flight(FlightParams(altitude=1000, speed=60, prf=300000, fov_deg=40))
    >>> round(plan.swath_width, 1), round(plan.density, 2)
    (727.9, 6.87)
    """
    half = math.radians(p.fov_deg) / 2
    B = 2 * p.altitude * math.tan(half)
    lps = LINES_PER_CYCLE[p.pattern] * p.scan_frequency
    d_along = p.speed / lps
    d_across = B * lps / p.prf
    rho = p.prf / (B * p.speed)
    spacing = B * (1 - p.overlap)
    n = max(math.ceil(max(p.area_width - B, 0.0) / spacing) + 1, 1)
    L = p.area_length + 2 * p.run_in
    R = p.speed ** 2 / (G * math.tan(math.radians(p.bank_deg)))
    t_turn = turn_length(spacing, R) / p.speed
    total = n * L / p.speed + (n - 1) * t_turn
    slant = p.altitude / math.cos(half)
    return FlightPlan(
        swath_width=B, spacing_along=d_along, spacing_across=d_across, density=rho,
        density_block=rho / (1 - p.overlap), nps=1 / math.sqrt(rho), flight_lines=n, line_spacing=spacing,
        line_length=L, turn_radius=R, turn_time_s=t_turn, total_time_s=total,
        max_prf_one_pulse_in_air=C_LIGHT / (2 * slant),
        pulses_in_air=max(math.ceil(p.prf * 2 * slant / C_LIGHT), 1),
        footprint_diameter=None if divergence_mrad is None else p.altitude * divergence_mrad * 1e-3,
        params=asdict(p),
    )


#: The unknowns :func:`solve_for_density` can solve for.
SOLVABLE = ("prf", "speed", "altitude")


def solve_for_density(target_density: float, p: FlightParams, solve: str = "prf") -> FlightParams:
    """The flight parameters that reach ``target_density`` (points/m^2 per pass).

    ``solve`` names the unknown: ``prf`` (Hz), ``speed`` (m/s) or ``altitude`` (m); the
    others are taken from ``p``. Check ``pulses_in_air`` of the resulting plan: above 1 the
    sensor must support multiple pulses in the air (MPiA).

    Examples
    --------
    >>> q = solve_for_density(10.0, FlightParams(altitude=1000, speed=60, fov_deg=40), "prf")
    >>> round(q.prf)
    436764
    """
    if not target_density > 0:
        raise InvalidInputError(f"target density {target_density} must be positive", field="density")
    k = 2 * math.tan(math.radians(p.fov_deg) / 2)
    if solve == "prf":
        q = FlightParams(**{**asdict(p), "prf": target_density * k * p.altitude * p.speed})
    elif solve == "speed":
        q = FlightParams(**{**asdict(p), "speed": p.prf / (target_density * k * p.altitude)})
    elif solve == "altitude":
        q = FlightParams(**{**asdict(p), "altitude": p.prf / (target_density * k * p.speed)})
    else:
        raise InvalidInputError(f"cannot solve for '{solve}'", "prf, speed or altitude", field="solve")
    if not all(math.isfinite(getattr(q, k)) and getattr(q, k) > 0 for k in ("prf", "speed", "altitude")):
        raise InvalidInputError(f"no finite {solve} reaches {target_density} points/m^2", field=solve)
    return q
