"""The planned curvature jumps (docs/feedforward.md, section 2b) from Python."""
import smoothsteer as ss


def test_planned_jumps_track_a_line_and_arc_path():
    """curvature_preview = planned_jumps from Python: valid with the exact target, and on a
    line-and-arc path the rear axle stays closer than with the centred ramp (C++ property test:
    JumpPlan.TracksLineAndArcPathsCloserThanTheCentredRamp)."""
    path = (ss.PathBuilder((0.0, 0.0), 0.0)
            .line(20.0).arc(30.0, 1.2).arc(40.0, -1.5).line(40.0).build())
    errors = {}
    for preview in (ss.CurvaturePreview.centred_ramp, ss.CurvaturePreview.planned_jumps):
        parameters = ss.ControllerParameters(
            lead_curvature_bound=0.1, feedforward_share=0.8, feedforward_curvature_rate=0.02,
            boundary_layer=0.01, cornering_target=ss.CorneringTarget.rear_axle_exact,
            curvature_preview=preview)
        parameters.validate()
        controller = ss.LeadWheelController(parameters, path)
        plant = ss.KinematicSingleTrack(parameters.vehicle_wheelbase_m)
        x, y, heading, worst = 0.0, 0.0, 0.0, 0.0
        for _ in range(int((path.length_m - 5.0) / (8.0 * 0.02))):
            output = controller.update((x, y), heading, 8.0, 0.0, 0.02)
            (x, y), heading = plant.step((x, y), heading, output.steering_angle_rad, 8.0, 0.02)
            worst = max(worst, abs(path.project((x, y)).lateral_error_m))
        errors[preview] = worst
    assert errors[ss.CurvaturePreview.planned_jumps] < 0.7 * errors[ss.CurvaturePreview.centred_ramp], errors

