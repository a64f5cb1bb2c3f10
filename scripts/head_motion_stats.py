#!/usr/bin/env python3
"""Head-motion statistics behind the viewcell's physical bound (docs/prediction.md,
"The physical bound"): for each path / trace file, the p99.9 over time of how far the
head moves and turns away from a constant-velocity extrapolation (velocity over the
25 ms before t) at horizons 0.05-2 s, and p99 / p99.9 / max of speed and acceleration
(central differences over +-25 ms). Plain python3, no numpy.

  scripts/head_motion_stats.py paths/city-walk.csv ../shared/traces/hololens_pred6dof/4.csv ...

Reads trimvr path files (t,px,py,pz,qx,qy,qz,qw) and the raw shared traces (HoloLens,
OptiTrack, Quest formats; magnitudes need no frame conversion)."""
import bisect
import csv
import math
import sys

W = 0.025
HORIZONS = [0.05, 0.1, 0.15, 0.2, 0.3, 0.5, 1.0, 2.0]


def load(fn):
    rows = []
    with open(fn) as f:
        lines = [l for l in f if l.strip() and not l.lstrip().startswith('#')]
    for r in csv.DictReader(lines):
        r = {k.strip(): v for k, v in r.items() if k}
        if 't' in r:
            t, p, q = float(r['t']), (r['px'], r['py'], r['pz']), (r['qx'], r['qy'], r['qz'], r['qw'])
        elif 'timestamp' in r:  # HoloLens: .NET ticks
            t, p, q = float(r['timestamp']) * 1e-7, (r['x'], r['y'], r['z']), (r['qx'], r['qy'], r['qz'], r['qw'])
        elif 't_header_s' in r:  # OptiTrack
            t, p, q = float(r['t_header_s']), (r['x'], r['y'], r['z']), (r['qx'], r['qy'], r['qz'], r['qw'])
        else:  # Questset
            t = float(r['time'])
            p = (r['HeadPosX'], r['HeadPosY'], r['HeadPosZ'])
            q = (r['HeadOrientationX'], r['HeadOrientationY'], r['HeadOrientationZ'], r['HeadOrientationW'])
        p = tuple(map(float, p))
        q = tuple(map(float, q))
        n = math.sqrt(sum(c * c for c in q))
        if rows and t <= rows[-1][0]:
            continue  # recorders repeat or reorder timestamps
        rows.append((t, p, tuple(c / n for c in q)))
    return rows


def qmul(a, b):
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return (aw * bx + ax * bw + ay * bz - az * by, aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw, aw * bw - ax * bx - ay * by - az * bz)


def qinv(a):
    return (-a[0], -a[1], -a[2], a[3])


def qlog(q):  # rotation vector (rad)
    x, y, z, w = q
    if w < 0:
        x, y, z, w = -x, -y, -z, -w
    n = math.sqrt(x * x + y * y + z * z)
    if n < 1e-12:
        return (2 * x, 2 * y, 2 * z)
    a = 2 * math.atan2(n, w)
    return (a * x / n, a * y / n, a * z / n)


def qexp(r):
    a = math.sqrt(sum(c * c for c in r))
    if a < 1e-12:
        return (0.0, 0.0, 0.0, 1.0)
    s = math.sin(a / 2) / a
    return (r[0] * s, r[1] * s, r[2] * s, math.cos(a / 2))


def sample(rows, ts, t):  # linear in position, normalised lerp in orientation
    i = max(0, min(bisect.bisect_right(ts, t) - 1, len(rows) - 2))
    t0, p0, q0 = rows[i]
    t1, p1, q1 = rows[i + 1]
    u = (t - t0) / (t1 - t0)
    if sum(q0[k] * q1[k] for k in range(4)) < 0:
        q1 = tuple(-c for c in q1)
    q = tuple(q0[k] + u * (q1[k] - q0[k]) for k in range(4))
    n = math.sqrt(sum(c * c for c in q))
    return tuple(p0[k] + u * (p1[k] - p0[k]) for k in range(3)), tuple(c / n for c in q)


def pct(v, p):
    v = sorted(v)
    return v[min(len(v) - 1, int(math.ceil(p / 100 * len(v))) - 1)]


def norm(v):
    return math.sqrt(sum(c * c for c in v))


def deviation(rows, ts, h):
    dp, dr = [], []
    t = ts[0] + W
    while t + h < ts[-1]:
        (p0, q0), (pa, qa), (ph, qh) = sample(rows, ts, t), sample(rows, ts, t - W), sample(rows, ts, t + h)
        v = [(p0[k] - pa[k]) / W for k in range(3)]
        w = [c / W * h for c in qlog(qmul(q0, qinv(qa)))]
        dp.append(norm([ph[k] - p0[k] - v[k] * h for k in range(3)]))
        dr.append(math.degrees(norm(qlog(qmul(qh, qinv(qmul(qexp(w), q0)))))))
        t += 0.01
    return pct(dp, 99.9), pct(dr, 99.9)


def derivatives(rows, ts, d=0.025):
    def vel(t):
        (pa, qa), (pb, qb) = sample(rows, ts, t - d), sample(rows, ts, t + d)
        return ([(pb[k] - pa[k]) / (2 * d) for k in range(3)], [c / (2 * d) for c in qlog(qmul(qb, qinv(qa)))])
    out = ([], [], [], [])
    t = ts[0] + 2 * d
    while t < ts[-1] - 2 * d:
        v, w = vel(t)
        va, wa = vel(t - d)
        vb, wb = vel(t + d)
        out[0].append(norm(v))
        out[1].append(norm([vb[k] - va[k] for k in range(3)]) / (2 * d))
        out[2].append(math.degrees(norm(w)))
        out[3].append(math.degrees(norm([wb[k] - wa[k] for k in range(3)])) / (2 * d))
        t += 0.005
    return [tuple(pct(s, p) for p in (99, 99.9, 100)) for s in out]


def main():
    print("| file | " + " | ".join("h = %g s" % h for h in HORIZONS) + " |")
    print("|---|" + "---|" * len(HORIZONS))
    stats = []
    for fn in sys.argv[1:]:
        rows = load(fn)
        ts = [r[0] for r in rows]
        cells = ["%.0f mm / %.1f°" % (1e3 * p, r) for p, r in (deviation(rows, ts, h) for h in HORIZONS)]
        print("| %s | %s |" % (fn, " | ".join(cells)))
        stats.append((fn, derivatives(rows, ts)))
    print("\n| file | speed m/s | acc m/s² | ang speed °/s | ang acc °/s² |  (p99 / p99.9 / max)")
    print("|---|---|---|---|---|")
    for fn, s in stats:
        print("| %s | %s |" % (fn, " | ".join("%.2f / %.2f / %.2f" % x for x in s)))


if __name__ == '__main__':
    main()
