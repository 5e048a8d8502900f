"""Benchmark: magbench.estimation.complementary_tilt against a per-sample Python loop.

Run as ``python benchmarks/bench_tilt.py [trial] [repeats]`` (defaults: the first BROAD
trial found, 5 repeats). The loop implements the same filter the way it is usually
written, one sample at a time with plain floats: advance the gyro quaternion, rotate the
accelerometer into its frame, step the second-order Butterworth low-pass (direct form II
transposed, started from the running mean of the first τ like the vectorised code),
take the shortest rotation to the vertical and compose. Both use the same gyro-bias
estimate (``estimation.rest_gyro_bias``, computed once outside the timing). Prints the
median wall time of each, their ratio, and the largest angle between the two results.

The peer library ``ahrs`` is not a dependency of magbench, so the loop is the reference.
It also times ``estimation.offline_tilt`` (the whole-record estimator, defaults) against
the peer ``vqf.offlineVQF`` (C++, its defaults, no magnetometer) on the same trial, with
the largest angle between their inclinations (the "up" axis in the sensor frame); the
peer's part is skipped when ``vqf`` is not installed.

Needs the BROAD recordings (see ``magbench.io.broad``); prints why and returns an empty
record when they are absent.
"""

import os

os.environ.setdefault("OMP_NUM_THREADS", "1")
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import math  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402

import numpy as np  # noqa: E402
from scipy.signal import butter, lfilter_zi  # noqa: E402

from magbench import estimation  # noqa: E402
from magbench.io import broad  # noqa: E402

TAU = 3.0


def loop_tilt(gyro, accel, dt, tau=TAU):
    """The filter of complementary_tilt (order 2, bias already removed), one sample at a time."""
    b, a = butter(2, math.sqrt(2.0) / (2.0 * math.pi * tau), fs=1.0 / dt)
    b0, b1, b2 = (float(v) for v in b)
    a1, a2 = float(a[1]), float(a[2])
    zi0, zi1 = (float(v) for v in lfilter_zi(b, a))
    warmup = max(1, int(round(tau / dt)))
    qw, qx, qy, qz = 1.0, 0.0, 0.0, 0.0
    total = [0.0, 0.0, 0.0]
    state = None
    out = np.empty((len(gyro), 4))
    for k in range(len(gyro)):
        # Gyro quaternion: q <- q ⊗ exp(ω dt / 2).
        wx, wy, wz = gyro[k, 0] * dt, gyro[k, 1] * dt, gyro[k, 2] * dt
        angle = math.sqrt(wx * wx + wy * wy + wz * wz)
        if angle > 0.0:
            s = math.sin(0.5 * angle) / angle
            dw, dx, dy, dz = math.cos(0.5 * angle), wx * s, wy * s, wz * s
            qw, qx, qy, qz = (qw * dw - qx * dx - qy * dy - qz * dz, qw * dx + qx * dw + qy * dz - qz * dy,
                              qw * dy - qx * dz + qy * dw + qz * dx, qw * dz + qx * dy - qy * dx + qz * dw)
        # Accelerometer into the gyro frame: v' = q v q*.
        vx, vy, vz = accel[k]
        tx, ty, tz = 2 * (qy * vz - qz * vy), 2 * (qz * vx - qx * vz), 2 * (qx * vy - qy * vx)
        ix = vx + qw * tx + (qy * tz - qz * ty)
        iy = vy + qw * ty + (qz * tx - qx * tz)
        iz = vz + qw * tz + (qx * ty - qy * tx)
        if k < warmup:
            total = [total[0] + ix, total[1] + iy, total[2] + iz]
            lx, ly, lz = (c / (k + 1) for c in total)
            if k == warmup - 1:
                state = [[zi0 * lx, zi1 * lx], [zi0 * ly, zi1 * ly], [zi0 * lz, zi1 * lz]]
        else:
            smooth = []
            for x, z in zip((ix, iy, iz), state):
                y = b0 * x + z[0]
                z[0] = b1 * x - a1 * y + z[1]
                z[1] = b2 * x - a2 * y
                smooth.append(y)
            lx, ly, lz = smooth
        # Shortest rotation taking (lx, ly, lz) to the vertical, then compose.
        n = math.sqrt(lx * lx + ly * ly + lz * lz)
        ux, uy, uz = lx / n, ly / n, lz / n
        cw, cx, cy = 1.0 + uz, uy, -ux
        cn = math.sqrt(cw * cw + cx * cx + cy * cy)
        cw, cx, cy = cw / cn, cx / cn, cy / cn
        out[k] = (cw * qw - cx * qx - cy * qy, cw * qx + cx * qw + cy * qz,
                  cw * qy - cx * qz + cy * qw, cw * qz + cx * qy - cy * qx)
    return out


def median_time(func, repeats):
    times, result = [], None
    for _ in range(repeats):
        t0 = time.perf_counter()
        result = func()
        times.append(time.perf_counter() - t0)
    return float(np.median(times)), result


def main(argv=()):
    argv = list(argv)
    names = broad.available_trials()
    if not names:
        print(broad.MISSING_MESSAGE)
        return {}
    name = argv[0] if argv else names[0]
    repeats = int(argv[1]) if len(argv) > 1 else 5
    trial = broad.load_trial(name)
    bias, _ = estimation.rest_gyro_bias(trial.gyro, trial.accel, trial.dt)
    gyro = trial.gyro - bias
    ours_s, ours = median_time(
        lambda: estimation.complementary_tilt(gyro, trial.accel, trial.dt, tau=TAU, rest_bias=False), repeats)
    loop_s, loop = median_time(lambda: loop_tilt(gyro, trial.accel, trial.dt), max(1, repeats // 2))
    dot = np.clip(np.abs(np.sum(ours * loop, axis=1)), 0.0, 1.0)
    max_angle = float(np.degrees(2 * np.arccos(dot)).max())
    print(f"trial {name}: {len(gyro)} samples")
    print(f"complementary_tilt (vectorised): {ours_s * 1e3:8.1f} ms")
    print(f"per-sample Python loop:          {loop_s * 1e3:8.1f} ms")
    print(f"speed-up: {loop_s / ours_s:.1f}x; largest difference between the two: {max_angle:.2e} deg")
    result = {"trial": name, "samples": len(gyro), "vectorised_s": ours_s, "loop_s": loop_s,
              "speedup": loop_s / ours_s, "max_difference_deg": max_angle}
    result.update(offline_timing(trial, repeats))
    return result


def _up(q):
    """The Earth's up axis in the sensor frame: the part of an orientation tilt determines."""
    w, x, y, z = np.asarray(q).T
    return np.stack([2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z], axis=1)


def offline_timing(trial, repeats):
    """offline_tilt against vqf.offlineVQF on one trial: median times and largest tilt gap."""
    gyro, accel = np.ascontiguousarray(trial.gyro), np.ascontiguousarray(trial.accel)
    ours_s, ours = median_time(lambda: estimation.offline_tilt(gyro, accel, trial.dt), repeats)
    print(f"offline_tilt:                    {ours_s * 1e3:8.1f} ms")
    record = {"offline_s": ours_s}
    try:
        import vqf
    except ImportError:
        print("vqf is not installed: offline_tilt not compared with vqf.offlineVQF")
        return record
    peer_s, peer = median_time(lambda: vqf.offlineVQF(gyro, accel, None, trial.dt)["quat6D"], repeats)
    cos = np.clip(np.sum(_up(ours) * _up(peer), axis=1), -1.0, 1.0)
    gap = float(np.degrees(np.arccos(cos)).max())
    print(f"vqf.offlineVQF (C++):            {peer_s * 1e3:8.1f} ms; ratio {ours_s / peer_s:.1f}; "
          f"largest inclination gap {gap:.3f} deg")
    record.update({"vqf_offline_s": peer_s, "offline_over_vqf": ours_s / peer_s,
                   "offline_vqf_max_gap_deg": gap})
    return record


if __name__ == "__main__":
    main(sys.argv[1:])
