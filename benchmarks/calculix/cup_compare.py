"""formsolve's axisymmetric cup against CalculiX's on the same scene
(benchmarks/calculix/cup.sh, doc/calculix.md): punch force over the stroke,
thickness along the blank's radius at 20 mm, and the ring of the wall
between z = -12 and -6 mm after the release: its hoop force and moment per
unit height and the opening of the ring cut there and slit, by the closed
form delta = 2 pi R (N / (E' t) + R M / (E' I)), E' = E / (1 - nu^2),
I = t^3 / 12, applied to both codes' residual hoop stress.

Usage: cup_compare.py OUT.csv OUT.png TIMES.csv LABEL=DAT:NX:NY ... LABEL=FORMSOLVE_DIR ...
"""
import csv
import glob
import math
import re
import sys

import numpy as np

def read_dat(path):
    """Blocks of a CalculiX .dat: list of (kind, set, time, rows)."""
    blocks, cur = [], None
    for line in open(path):
        m = re.search(r'^\s*(.*?)\s*\(.*\)\s*for set (\S+) and time\s+(\S+)', line)
        if m:
            cur = [m.group(1), m.group(2), float(m.group(3)), []]
            blocks.append(cur)
        elif cur is not None and line.strip():
            cur[3].append([float(v) for v in line.split()])
    return blocks

def last(blocks, kind, name, time=None):
    sel = [b for b in blocks if b[0].startswith(kind) and b[1] == name and (time is None or abs(b[2] - time) < 1e-9)]
    return np.array(sel[-1][3]) if sel else None

def ccx_force(blocks, stroke):
    pts = [(b[2] * stroke, -b[3][0][1] * 180) for b in blocks
           if b[0].startswith('total force') and b[1] == 'PUNCHN' and b[2] <= 1 + 1e-12]
    return np.array(pts)

def band_ring(stress, coords, area, rmid_of_z, z0, z1, E, nu):
    """Over the band z0 < z < z1 of the wall: the hoop force N and moment M
    per unit height, the mid radius, the wall thickness and the opening of
    the ring cut there and slit (closed form, doc/calculix.md)."""
    Ep = E / (1 - nu ** 2)
    sel = (coords[:, 1] > z0) & (coords[:, 1] < z1)
    rm = rmid_of_z(coords[sel, 1])
    s = coords[sel, 0] - rm
    h = z1 - z0
    t = area[sel].sum() / h
    N = (stress[sel] * area[sel]).sum() / h
    M = (stress[sel] * s * area[sel]).sum() / h
    R = rm.mean()
    I = t ** 3 / 12
    return N, M, R, t, 2 * math.pi * R * (N / (Ep * t) + R * M / (Ep * I))

def seg_distance(p, a, b):
    """Distance of points p (n,2) from the polyline a->b segments (m,2)."""
    d = b - a
    L2 = (d ** 2).sum(1)
    tt = np.clip(((p[:, None, :] - a[None]) * d[None]).sum(2) / L2[None], 0, 1)
    q = a[None] + tt[..., None] * d[None]
    return np.sqrt(((p[:, None, :] - q) ** 2).sum(2)).min(1)

def wall_rmid(mid):
    """r of the mid-surface as a function of z along the wall (r > 15 mm)."""
    w = mid[mid[:, 0] > 15]
    w = w[np.argsort(w[:, 1])]
    return lambda z: np.interp(z, w[:, 1], w[:, 0])

def ccx_state(blocks, NX, R0, time):
    bot, top = last(blocks, 'displacements', 'BOTN', time), last(blocks, 'displacements', 'TOPN', time)
    r0 = np.array([R0 * i / (2 * NX) for i in range(2 * NX + 1)])
    T = 0.78
    pb = np.c_[r0 + bot[:, 1], bot[:, 2]]
    pt = np.c_[r0 + top[:, 1], T + top[:, 2]]
    thick = seg_distance(pb, pt[:-1], pt[1:])
    return r0, pb, pt, thick

def ccx_ips(blocks, time, NX, NY, R0, T):
    """Hoop stress and the deformed position and section area of each
    integration point (CalculiX prints the points' initial coordinates)."""
    s = last(blocks, 'stresses', 'SHEET', time)
    c = last(blocks, 'global coordinates', 'SHEET', time)
    u = last(blocks, 'displacements', 'SHEETN', time)
    disp = {int(r[0]): r[1:3] for r in u}
    def node_id(i, j):
        return 1 + j * (2 * NX + 1) + i
    shape = [(-1, -1), (1, -1), (1, 1), (-1, 1), (0, -1), (1, 0), (0, 1), (-1, 0)]
    def N(xi, eta):
        out = []
        for a, b in shape:
            if a and b:
                out.append(0.25 * (1 + a * xi) * (1 + b * eta) * (a * xi + b * eta - 1))
            elif a == 0:
                out.append(0.5 * (1 - xi ** 2) * (1 + b * eta))
            else:
                out.append(0.5 * (1 + a * xi) * (1 - eta ** 2))
        return np.array(out)
    def dN(xi, eta, h=1e-6):
        return (N(xi + h, eta) - N(xi - h, eta)) / (2 * h), (N(xi, eta + h) - N(xi, eta - h)) / (2 * h)
    pos, area = np.zeros((len(s), 2)), np.zeros(len(s))
    hx, hy = R0 / NX, T / NY
    for k, row in enumerate(c):
        e = int(row[0]) - 1
        ii, jj = e % NX, e // NX
        i, j = 2 * ii, 2 * jj
        ids = [node_id(i, j), node_id(i + 2, j), node_id(i + 2, j + 2), node_id(i, j + 2),
               node_id(i + 1, j), node_id(i + 2, j + 1), node_id(i + 1, j + 2), node_id(i, j + 1)]
        X = np.array([[R0 * (i + 1 + a) / (2 * NX), T * (j + 1 + b) / (2 * NY)] for a, b in shape])
        x = X + np.array([disp[n] for n in ids])
        xi = 2 * (row[2] / math.cos(math.atan2(row[4], row[2])) - X[:4, 0].mean()) / hx
        eta = 2 * (row[3] - X[:4, 1].mean()) / hy
        pos[k] = N(xi, eta) @ x
        a, b = dN(xi, eta)
        J = np.array([a @ x, b @ x])
        # 2x2x2 points, each an eighth of the element: weight 1 of 4 in the section
        area[k] = abs(np.linalg.det(J)) * 4 / 8
    return pos, s[:, 4], area   # szz: the hoop stress

def formsolve_ips(pvtu):
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
    r = vtk.vtkXMLPUnstructuredGridReader(); r.SetFileName(pvtu); r.Update()
    o = r.GetOutput()
    pts = vtk_to_numpy(o.GetPoints().GetData())[:, :2]
    hoop = vtk_to_numpy(o.GetPointData().GetArray('residual_stress_hoop'))
    coords, stress, area = [], [], []
    for c in range(o.GetNumberOfCells()):
        ids = [o.GetCell(c).GetPointId(k) for k in range(o.GetCell(c).GetNumberOfPoints())]
        u = pts[ids]
        o_ = np.argsort(np.arctan2(u[:, 1] - u[:, 1].mean(), u[:, 0] - u[:, 0].mean()))
        u = u[o_]
        area.append(0.5 * abs(np.dot(u[:, 0], np.roll(u[:, 1], 1)) - np.dot(u[:, 1], np.roll(u[:, 0], 1))))
        coords.append(pts[ids].mean(0)); stress.append(hoop[ids[0]])
    return np.array(coords), np.array(stress), np.array(area)


R0, T, E, NU, STROKE, Z0, Z1 = 38.5, 0.78, 210000.0, 0.3, 20.0, -12.0, -6.0


def ccx_case(dat, NX, NY):
    blocks = read_dat(dat)
    r0, _, _, thick = ccx_state(blocks, NX, R0, 1.0)
    tmax = max(b[2] for b in blocks)
    _, pb, pt, _ = ccx_state(blocks, NX, R0, tmax)
    c, s, a = ccx_ips(blocks, tmax, NX, NY, R0, T)
    return dict(force=ccx_force(blocks, STROKE), r0=r0, thick=thick, ips=(c, s, a), mid=0.5 * (pb + pt))


def formsolve_case(d):
    hist = list(csv.DictReader(open(f'{d}/history.csv')))
    sheet = list(csv.DictReader(open(f'{d}/sheet.csv')))
    prof = list(csv.DictReader(open(f'{d}/springback-profile.csv')))
    return dict(force=np.array([(float(h['punch_travel']), float(h['punch_force'])) for h in hist]),
                r0=np.array([float(h['reference_radius']) for h in sheet]),
                thick=np.array([float(h['thickness']) for h in sheet]),
                ips=formsolve_ips(sorted(glob.glob(f'{d}/springback_*.pvtu'))[-1]),
                mid=np.array([(float(h['r_sprung']), float(h['z_sprung'])) for h in prof]))


def measures(case):
    f = case['force']
    out = {f'force_{s}mm': np.interp(s, f[:, 0], f[:, 1]) for s in (5, 10, 15, 20)}
    out['peak_force'] = f[:, 1].max()
    out['min_thickness'] = case['thick'].min()
    out['min_thickness_r0'] = case['r0'][case['thick'].argmin()]
    out['max_thickness'] = case['thick'].max()
    c, s, a = case['ips']
    N, M, R, t, d = band_ring(s, c, a, wall_rmid(case['mid']), Z0, Z1, E, NU)
    out.update(ring_N=N, ring_M=M, ring_R=R, ring_t=t, ring_opening=d)
    return out


def chart(cases, times, png):
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(2, 2, figsize=(11, 8))
    for label, c in cases.items():
        style = '--' if label.startswith('CalculiX') else '-'
        ax[0, 0].plot(c['force'][:, 0], c['force'][:, 1] / 1000, style, label=label)
        ax[0, 1].plot(c['r0'], c['thick'], style, label=label)
        pos, s, a = c['ips']
        sel = (pos[:, 1] > -9.5) & (pos[:, 1] < -8.5)
        rm = wall_rmid(c['mid'])(pos[sel, 1])
        o = np.argsort(pos[sel, 0] - rm)
        ax[1, 0].plot((pos[sel, 0] - rm)[o], s[sel][o], '.' if style == '-' else 'x', label=label)
    ax[0, 0].set(xlabel='punch stroke (mm)', ylabel='punch force (kN)', title='Punch force')
    ax[0, 1].set(xlabel='initial radius (mm)', ylabel='thickness at 20 mm (mm)', title='Thickness')
    ax[1, 0].set(xlabel='distance from the mid-surface, outward (mm)', ylabel='residual hoop stress (MPa)',
                 title='Wall at z = -9 mm after the release')
    for a_ in (ax[0, 0], ax[0, 1], ax[1, 0]):
        a_.grid(alpha=0.3)
        a_.legend(fontsize=8)
    names = [t[0] for t in times]
    ax[1, 1].barh(names, [t[1] for t in times], color=['C0' if not n.startswith('CalculiX') else 'C3' for n in names])
    ax[1, 1].set(xlabel='wall time, draw and release (s, 1 core)', title='Time')
    ax[1, 1].set_xscale('log')
    fig.tight_layout()
    fig.savefig(png, dpi=90)


def main():
    out_csv, png, times_csv = sys.argv[1:4]
    cases = {}
    for arg in sys.argv[4:]:
        label, spec = arg.split('=', 1)
        if spec.endswith('.dat') or '.dat:' in spec:
            dat, nx, ny = spec.split(':')
            cases[label] = ccx_case(dat, int(nx), int(ny))
        else:
            cases[label] = formsolve_case(spec)
    rows = {label: measures(c) for label, c in cases.items()}
    keys = list(next(iter(rows.values())).keys())
    with open(out_csv, 'w') as f:
        f.write('measure,' + ','.join(rows) + '\n')
        for k in keys:
            f.write(k + ',' + ','.join(f'{rows[l][k]:.6g}' for l in rows) + '\n')
    times = [(r[0], float(r[1])) for r in csv.reader(open(times_csv))]
    chart(cases, times, png)
    print(open(out_csv).read())


if __name__ == '__main__':
    main()
