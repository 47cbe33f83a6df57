"""Sensor faults and reset() from Python: the observer's gates report what they dropped and
rejected (SideSlipDiagnostics.sensors, SensorFault bits), and reset() refuses an angle that is
no steering angle with ControllerError instead of wrapping it."""
import math

import numpy as np
import pytest

import smoothsteer as ss
from conftest import ROOT

VEHICLE = ROOT / "vehicles" / "passenger_car.yaml"


def example_system():
    car = ss.VehicleDescription(vehicle=ss.VehicleParameters.from_file(str(VEHICLE)))
    path = ss.Path.from_waypoints(np.array([(0, 0), (30, 0), (60, 3.5), (90, 3.5)], dtype=float))
    return ss.make_steering_system(car, path, ss.SteeringSystemOptions(max_speed_mps=15.0))


def drive(system, steps, gyro=lambda k: 0.0, accelerometer=lambda k: 0.0, start=0):
    out = None
    for k in range(start, start + steps):
        out = system.update((12.0 * 0.02 * k, 0.1), 0.0, 12.0, yaw_rate_radps=gyro(k),
                            lateral_acceleration_mps2=accelerometer(k), period_s=0.02,
                            steering_angle_rad=0.0)
    return out


def test_a_gyro_spike_is_rejected_and_counted():
    system = example_system()
    drive(system, 50)
    out = drive(system, 1, gyro=lambda k: 1.0, start=50)
    assert out.side_slip.sensors.yaw_rate_rejected == 1
    assert out.side_slip.sensors.last_period & ss.SensorFault.yaw_rate_implausible
    assert out.side_slip.estimate_trusted
    assert abs(out.side_slip.rear_axle_side_slip_rad) < 1e-3


def test_a_nan_sample_is_dropped_not_an_error():
    system = example_system()
    drive(system, 50)
    out = drive(system, 1, accelerometer=lambda k: math.nan, start=50)
    assert out.side_slip.observer_status == ss.Status.ok
    assert out.side_slip.sensors.lateral_acceleration_dropped == 1
    assert out.side_slip.sensors.last_period == ss.SensorFault.lateral_acceleration_dropped


def test_fault_gate_is_a_keyword_group():
    gate = ss.SideSlipFaultGate(innovation_gate=36.0)
    observer = ss.SideSlipObserverParameters(fault_gate=gate)
    assert observer.fault_gate.innovation_gate == 36.0
    observer.fault_gate = ss.SideSlipFaultGate(innovation_gate=1.0)
    with pytest.raises(ValueError, match="fault_gate.innovation_gate"):
        observer.validate()


@pytest.mark.parametrize("angle", [2.0, -2.0, 4.0, math.nan, math.inf, 1.1])
def test_reset_refuses_what_is_no_steering_angle(angle):
    system = example_system()
    with pytest.raises(ss.ControllerError, match="invalid_input"):
        system.reset(angle)
    system.reset(0.3)  # beyond the certified set but a steering angle: approached, not refused


def test_steering_offset_is_learned_reported_kept_and_forgotten():
    # The car drives straight (gyro and accelerometer read 0) while its angle sensor reads
    # 0.01 rad: the road wheels steer 0.01 rad less than measured.
    system = example_system()

    def straight(steps, start=0):
        out = None
        for k in range(start, start + steps):
            out = system.update((12.0 * 0.02 * k, 0.0), 0.0, 12.0, yaw_rate_radps=0.0,
                                lateral_acceleration_mps2=0.0, period_s=0.02,
                                steering_angle_rad=0.01)
        return out

    out = straight(150)
    assert out.side_slip.steering_offset_rad == pytest.approx(-0.01, abs=2e-3)
    assert abs(out.side_slip.rear_axle_side_slip_rad) < 1e-3
    system.reset(0.0)
    assert straight(1, start=150).side_slip.steering_offset_rad == pytest.approx(-0.01, abs=2e-3)
    system.forget_steering_offset()
    # Below the learning speed the offset stays where forget_steering_offset() put it.
    slow = system.update((36.0, 0.0), 0.0, 2.5, yaw_rate_radps=0.0, lateral_acceleration_mps2=0.0,
                         period_s=0.02, steering_angle_rad=0.01)
    assert slow.side_slip.steering_offset_rad == 0.0
    observer = ss.SideSlipObserverParameters(max_steering_offset_rad=0.3)
    with pytest.raises(ValueError, match="max_steering_offset_rad"):
        observer.validate()


def test_the_pose_age_is_estimated_unless_given_or_switched_off():
    # A pose that stops changing ages by a period each period; a given age is taken as it is.
    system = example_system()
    out = None
    for k in range(10):
        out = system.update((1.0, 0.0), 0.0, 12.0, period_s=0.02)
    assert out.pose_age_s == pytest.approx(9 * 0.02)
    assert system.update((1.0, 0.0), 0.0, 12.0, period_s=0.02, pose_age_s=0.05).pose_age_s == 0.05
    assert ss.SteeringSystemParameters(estimate_pose_age=False).estimate_pose_age is False
