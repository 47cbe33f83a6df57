"""smoothsteer: n-smooth, differentially bounded path-tracking control for car-like vehicles.

Python bindings of the C++ library (Festl, Stolz, Watzenig, "Multi-objective path tracking
control for car-like vehicles with differentially bounded n-smooth output"). SI units
throughout: metres, radians, seconds. See docs/python.md.

    import smoothsteer as ss
    path = ss.Path.circle((0, 0), 30.0)
    controller = ss.LeadWheelController(ss.ControllerParameters(), path)
    out = controller.update((-50.0, 20.0), 1.0, 8.0)   # rear axle (x, y), heading, speed
    out.steering_angle_rad, out.diagnostics.lateral_error_m
"""
import json as _json

from ._smoothsteer import (  # noqa: F401
    __version__,
    ActiveLimit,
    ActuatorInversion,
    ActuatorParameters,
    ChainParameters,
    CourseErrorParameters,
    DelayCompensation,
    DisturbanceEstimation,
    DrivingDomain,
    FeedforwardParameters,
    FrictionGuard,
    SingleTrackInversion,
    SwitchingLawParameters,
    ObserverTireModel,
    SensorFault,
    SideSlipDiagnostics,
    SideSlipFaultGate,
    SideSlipObserverHealth,
    SideSlipObserverParameters,
    SlipInput,
    SteeringSystem,
    SteeringSystemOptions,
    SteeringSystemOutput,
    SteeringSystemParameters,
    TireParameters,
    VehicleDescription,
    VehicleParameters,
    actuator_group_delay_s,
    describe_active_limits,
    make_steering_system,
    speed_compensation,
    steering_system_controller,
    ChainBounds,
    Certificate,
    ComparisonController,
    ConfigError,
    ControllerError,
    ControllerOutput,
    ControllerParameters,
    CuspSequencer,
    Gear,
    KinematicSingleTrack,
    PathPlan,
    CorneringTarget,
    CurvaturePreview,
    GainSchedule,
    HosmController,
    Imperfection,
    InfeasibleLimits,
    LeadWheelController,
    Path,
    PathBuilder,
    WaypointConditioner,
    WaypointConditionerParameters,
    estimate_waypoint_jitter,
    PathPoint,
    PathProjection,
    ReachingBenchmarkOptions,
    ReachingProblem,
    SaturationStatistics,
    PlannerWindows,
    PlantActuatorScales,
    PlantScales,
    Scenario,
    ScheduledController,
    SideForce,
    SideSlipEstimation,
    SideSlipSource,
    SimulationParameters,
    SpeedCompensation,
    SlidingSurface,
    Status,
    SteeringCertificate,
    SteeringController,
    SteeringGovernor,
    TrackingDiagnostics,
    TuningOptions,
    VehicleLimits,
    comparison_controller_names,
    compare_robustness,
    compare_tight_corners,
    default_imperfections,
    governed_feedforward_rate,
    governed_law_length,
    governed_parameters,
    governed_reversal_curvature,
    governed_reversal_heading_rad,
    parameters_for_vehicle,
    preview_curvature,
    scaled_plant_vehicle,
    scenario_certificate,
    simulate_kinematic,
    solve_kinetic_reference,
    solve_optimal_reaching,
    trace_column_names,
)
from . import _smoothsteer


def _override_text(value):
    """A Python value as the YAML text of a --set override."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (int, float, str)):
        return repr(value) if isinstance(value, float) else str(value)
    return _json.dumps(value)  # lists and mappings: JSON is YAML flow syntax


def _overrides(overrides):
    """{"controller.k_rob": 0.2} or ["controller.k_rob=0.2"] -> ["controller.k_rob=0.2"]."""
    if overrides is None:
        return []
    if isinstance(overrides, dict):
        return [f"{key}={_override_text(value)}" for key, value in overrides.items()]
    if isinstance(overrides, str):
        raise TypeError("overrides: give a dict {key: value} or a list of 'key=value' strings")
    return [str(item) for item in overrides]


def load_scenario(file, overrides=None, reuse_files=False):
    """Loads a scenario YAML (docs/scenarios.md) with overrides applied.

    overrides: a dict {"controller.k_rob": 0.2, ...} or a list of "key=value" strings, the
    same as the CLI's --set. Raises ConfigError naming the file, the key and the rule.
    reuse_files: parse the scenario file and the vehicle files it names once per process (for
    many loads of one file with other overrides, docs/campaigns.md); the same result and errors.
    """
    load = _smoothsteer._load_scenario_reusing_files if reuse_files else _smoothsteer._load_scenario
    return load(str(file), _overrides(overrides))


def run_scenario(file, overrides=None):
    """Simulates a scenario as `smoothsteer run` does: returns (trace, summary).

    file: a scenario YAML path or a Scenario from load_scenario(). trace is a dict of numpy
    arrays keyed by the trace.csv columns (trace_column_names(); t [s], x [m], e [m],
    delta_cmd [rad], delta_cmd_rate [rad/s], ...), summary the content of summary.json as a
    dict. The simulation runs without the GIL, so threads can run scenarios in parallel.
    """
    scenario = file if isinstance(file, Scenario) else load_scenario(file, overrides)
    if isinstance(file, Scenario) and overrides:
        raise TypeError("run_scenario: overrides apply to a file, not to a loaded Scenario")
    return _smoothsteer._run_scenario(scenario)


class Schedule(dict):
    """A gain schedule as a dict of numpy arrays over speed (speed_mps [m/s], region,
    fictive_wheelbase_m [m], lead_wheelbase_m [m], lead_curvature_bound [1/m], k_rob,
    feedforward_curvature_bound [1/m], feedforward_curvature_rate [1/m^2],
    max_steering_angle_rad [rad], max_steering_rate_radps [rad/s],
    max_steering_acceleration_radps2 [rad/s^2]); `gain_schedule` is the GainSchedule that
    ScheduledController drives."""

    def __init__(self, gain_schedule):
        super().__init__(gain_schedule.arrays())
        self.gain_schedule = gain_schedule


def tune(vehicle, speeds, path=None, **options):
    """Certified parameters over speed for a car (docs/tuning.md), as `smoothsteer tune`.

    vehicle: VehicleLimits or a vehicle YAML path; speeds: increasing speeds [m/s]; path: a
    Path whose curvature and curvature rate the feedforward must follow; options: TuningOptions
    fields (certificate="feedforward" or "box", order=2, path_curvature_bound=..., ...).
    Returns a Schedule (dict of numpy arrays). Raises InfeasibleLimits naming the speed and
    the binding limit, ValueError for bad inputs.
    """
    if isinstance(vehicle, str):
        vehicle = VehicleLimits.from_file(vehicle)
    if isinstance(options.get("certificate"), str):
        options["certificate"] = Certificate.__members__[options["certificate"]]
    speeds = [float(v) for v in speeds]
    return Schedule(_smoothsteer._tune(vehicle, speeds, path, TuningOptions(**options)))


__all__ = [name for name in dir() if not name.startswith("_")]
