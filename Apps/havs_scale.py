# Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
"""havs_scale: the benchmark's scale section (issue 43).

    python3 Apps/havs_scale.py [--build build] [--output-dir Documentation/scale]
                               [--sizes 1,5,10,25,50] [--mappers havs,tetraycast,cellproj,pt]
                               [--size 512] [--memory-limit-gb G]
    python3 Apps/havs_scale.py --check 50 [--check-size 256] [--check-mappers havs,tetraycast]

For each size (millions of tetrahedra: a block of n^3 cubes, 5 tetrahedra each,
vtkHAVSDataSets::MakeGenerated, the field sin(6x) cos(5y) + z) and each mapper,
side by side, one child process each (peak memory only grows): the first image
(the mesh, the orders, the table, the uploads, the shaders) and a new view
(the median of three 30-degree turns), each ended by a read-back of the window;
the memory beyond the loaded grid (the grid's resident size after malloc_trim
is the base; the process's peak resident size is reset there through
/proc/self/clear_refs): the peak during the two, and what is kept after them;
and, for the project's mappers, their memory ledger (vtkHAVSMapperBase::
GetMemoryParts: the mesh, the orders, the records, the GPU buffers; on llvmpipe
the GPU buffers live in host memory, as does the rasterizer's own memory,
which the ledger does not see). A configuration whose memory, extrapolated
from the same mapper's bytes per tetrahedron at the largest size measured
before, would not fit in the memory limit (default: MemAvailable less 2 GB)
is not run; its row says so.

Writes scale.csv, scale.md (the table) and, with matplotlib, scale.png (time
and memory against size) in the output directory. Every row says the SMP
backend (STDThread) and the renderer.

--check M instead renders each of --check-mappers (default HAVS) on the block
of about M million tetrahedra at --check-size^2 and the exact reference
(vtkHAVSReferenceRenderer) of the same grid and view, each in its own
process, and compares the float images against MISSION.md's bound (RMSE <
5e-4, largest difference < 0.01); each one's control, its frame with the
camera turned half a degree, must miss the bound. Writes check.md; exits 1 if
any fails.
"""
import argparse
import csv
import ctypes
import json
import os
import re
import subprocess
import sys
import time

MAPPERS = {
    'havs': 'vtkHAVSVolumeMapper (defaults)',
    'tetraycast': 'vtkHAVSRayCastMapper',
    'cellproj': 'vtkHAVSCellProjectionMapper',
    'pt': "VTK's vtkProjectedTetrahedraMapper",
}


def cubes_for(millions):
    """Cubes per side for about `millions` million tetrahedra (5 per cube)."""
    return max(2, round((millions * 1e6 / 5.0) ** (1.0 / 3.0)))


def status_mb(key):
    with open('/proc/self/status') as f:
        for line in f:
            if line.startswith(key):
                return int(line.split()[1]) / 1024.0
    return float('nan')


def make_scene(mapper_name, cubes, size):
    """The grid, the mapper, its volume and property, and a window with the scale's camera."""
    import vtkhavs
    from vtkmodules.vtkRenderingCore import vtkVolume
    from vtkmodules.vtkRenderingVolumeOpenGL2 import vtkOpenGLProjectedTetrahedraMapper

    grid = vtkhavs.vtkHAVSDataSets.MakeGenerated(cubes)
    prop = make_property(grid)
    make = {'havs': vtkhavs.vtkHAVSVolumeMapper, 'tetraycast': vtkhavs.vtkHAVSRayCastMapper,
            'cellproj': vtkhavs.vtkHAVSCellProjectionMapper,
            'pt': vtkOpenGLProjectedTetrahedraMapper}[mapper_name]
    mapper = make()
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    return grid, mapper, volume


def make_window(volume, size):
    """A window of size^2 whose renderer shows `volume` (made after the memory base)."""
    import vtkhavs
    from vtkmodules.vtkRenderingCore import vtkRenderer
    window = vtkhavs.vtkHAVSRenderWindowFactory.CreateRenderWindow()
    window.SetSize(size, size)
    renderer = vtkRenderer()
    window.AddRenderer(renderer)
    renderer.AddVolume(volume)
    return window, renderer


def make_property(grid, scalar_range=None, length=None):
    """The scale's transfer function over the grid's scalar range, its opacity
    unit a 40th of the grid's length (or over `scalar_range` and `length`)."""
    from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
    from vtkmodules.vtkRenderingCore import vtkColorTransferFunction, vtkVolumeProperty
    lo, hi = scalar_range or grid.GetPointData().GetScalars().GetRange()
    color = vtkColorTransferFunction()
    color.AddRGBPoint(lo, 0.2, 0.3, 1.0)
    color.AddRGBPoint(hi, 1.0, 0.4, 0.1)
    opacity = vtkPiecewiseFunction()
    opacity.AddPoint(lo, 0.0)
    opacity.AddPoint(hi, 0.8)
    prop = vtkVolumeProperty()
    prop.SetColor(color)
    prop.SetScalarOpacity(opacity)
    prop.SetScalarOpacityUnitDistance((length or grid.GetLength()) / 40.0)
    return prop


def set_camera(grid, renderer):
    """The scale's view: the block's default view turned 20 and 15 degrees."""
    camera = renderer.GetActiveCamera()
    renderer.ResetCamera(grid.GetBounds())
    camera.Azimuth(20)
    camera.Elevation(15)
    renderer.ResetCameraClippingRange(grid.GetBounds())
    return camera


def check_worker(kind, cubes, size, out):
    """The check: `kind` 'reference' (the exact image) or a mapper name (its float
    result, the scale's view); writes <out>/check-<kind>-<cubes>.f32 (RGBA, bottom
    row first) and prints one JSON line (seconds, peak memory beyond the grid)."""
    import vtkhavs
    from vtkmodules.vtkCommonCore import vtkFloatArray

    trim = ctypes.CDLL('libc.so.6').malloc_trim
    grid, mapper, volume = make_scene('havs' if kind == 'reference' else kind, cubes, size)
    tets = grid.GetNumberOfCells()
    trim(0)
    base = status_mb('VmRSS:')
    with open('/proc/self/clear_refs', 'w') as f:
        f.write('5')
    window, renderer = make_window(volume, size)
    camera = set_camera(grid, renderer)
    t0 = time.time()
    if kind == 'reference':
        reference = vtkhavs.vtkHAVSReferenceRenderer()
        reference.SetInputData(grid)
        reference.SetProperty(volume.GetProperty())
        reference.SetCamera(camera)
        reference.SetSize(size, size)
        ok = reference.Render()
        image = reference.GetImage()
    else:
        mapper.SetInputData(grid)
        mapper.KeepFloatResultOn()
        window.Render()
        image = vtkFloatArray()
        dims = [0, 0]
        ok = mapper.GetFloatResult(image, dims) and dims == [size, size]
    seconds = time.time() - t0
    if ok and kind != 'reference':
        # The control: the same mapper and grid, the camera turned half a degree.
        save(image, size, os.path.join(out, 'check-%s-%d.f32' % (kind, cubes)))
        camera.Azimuth(0.5)
        window.Render()
        ok = mapper.GetFloatResult(image, dims)
    peak = status_mb('VmHWM:')
    if not ok:
        print('HAVS_CHECK ' + json.dumps({'kind': kind, 'tets': tets, 'failed': True}))
        return
    save(image, size, os.path.join(
        out, 'check-%s-%d.f32' % (kind if kind == 'reference' else kind + '-turned', cubes)))
    print('HAVS_CHECK ' + json.dumps({'kind': kind, 'tets': tets, 'size': size,
                                      'seconds': seconds, 'peak_mb': peak - base}), flush=True)


def save(image, size, path):
    """A vtkFloatArray's RGBA values as raw floats."""
    import array
    values = array.array('f', (image.GetValue(i) for i in range(4 * size * size)))
    with open(path, 'wb') as f:
        values.tofile(f)


def compare_images(a_path, b_path, size=0):
    """RMSE and largest difference over every RGBA component (vtkHAVSImageMetrics');
    with `size`, also the pixels off by more than 0.01, how many of them lie on
    the silhouette (a pixel of b's 3x3 neighbourhood empty), and the worst pixel."""
    import array
    a, b = array.array('f'), array.array('f')
    with open(a_path, 'rb') as f:
        a.frombytes(f.read())
    with open(b_path, 'rb') as f:
        b.frombytes(f.read())
    if len(a) != len(b) or not a:
        return float('inf'), float('inf')
    squares = sum((x - y) ** 2 for x, y in zip(a, b))
    rmse, largest = (squares / len(a)) ** 0.5, max(abs(x - y) for x, y in zip(a, b))
    if not size:
        return rmse, largest
    off, silhouette, worst = 0, 0, (0.0, 0, 0)
    for y in range(size):
        for x in range(size):
            p = 4 * (y * size + x)
            d = max(abs(a[p + c] - b[p + c]) for c in range(4))
            if d <= 0.01:
                continue
            off += 1
            worst = max(worst, (d, x, y))
            if any(b[4 * (v * size + u) + 3] == 0.0 for v in range(max(0, y - 1), min(size, y + 2))
                   for u in range(max(0, x - 1), min(size, x + 2))):
                silhouette += 1
    return rmse, largest, off, silhouette, worst


def check(a, env):
    """Each of --check-mappers at the largest size against the exact reference
    at --check-size, each with a control: the same mapper's frame with the
    camera turned half a degree must miss the bound."""
    cubes = cubes_for(a.check)
    mappers = a.check_mappers.split(',')
    results = {}
    for kind in mappers + ['reference']:
        r = subprocess.run([sys.executable, os.path.abspath(__file__), '--check-worker', kind,
                            str(cubes), str(a.check_size), a.output_dir], env=env,
                           capture_output=True, text=True)
        line = [l for l in r.stdout.split('\n') if l.startswith('HAVS_CHECK ')]
        if r.returncode != 0 or not line or 'failed' in line[0]:
            print('havs_scale: the check\'s %s failed (exit %d): %s %s'
                  % (kind, r.returncode, line, r.stderr.strip()[-300:]))
            return 1
        results[kind] = json.loads(line[0][len('HAVS_CHECK '):])
        print('check: %s' % line[0], flush=True)
    path = lambda kind: os.path.join(a.output_dir, 'check-%s-%d.f32' % (kind, cubes))
    ref = results['reference']
    per = 2 ** 20 / ref['tets']
    names = ', '.join(MAPPERS[m] for m in mappers)
    text = ['# Scale: the largest mesh checked against the exact reference', '',
            'Made by `python3 Apps/havs_scale.py --check %g --check-size %d --check-mappers %s` '
            '(%s; vtkSMPTools %s). %s on the block of %s tetrahedra, the scale\'s view at '
            '%d^2, each float result against vtkHAVSReferenceRenderer\'s exact image of the '
            'same grid and camera, over every RGBA component (MISSION.md\'s bound: RMSE < '
            '5e-4, largest difference < 0.01). Each in a process of its own; seconds are the '
            'first image (a mapper\'s: the mesh, the orders, the table, the draw) and the whole '
            'reference; memory beyond the loaded grid (a mapper\'s row: its two frames).'
            % (a.check, a.check_size, a.check_mappers, time.strftime('%Y-%m-%d'),
               env.get('VTK_SMP_BACKEND_IN_USE', 'Sequential'), names,
               format(ref['tets'], ','), a.check_size), '',
            '| image | seconds | peak B/tet beyond the grid | RMSE | largest difference | '
            'within the bound |', '|---|---|---|---|---|---|']
    notes = []
    passed = True
    for m in mappers:
        rmse, largest, off, silhouette, worst = compare_images(path(m), path('reference'),
                                                               a.check_size)
        control_rmse, control_largest = compare_images(path(m + '-turned'), path('reference'))
        exact = rmse < 5e-4 and largest < 0.01
        control_fails = not (control_rmse < 5e-4 and control_largest < 0.01)
        passed = passed and exact and control_fails
        r = results[m]
        text.append('| %s | %.1f | %.0f | %.2e | %.2e | %s |' % (
            MAPPERS[m], r['seconds'], r['peak_mb'] * per, rmse, largest,
            'yes' if exact else 'NO'))
        text.append('| control: %s, the camera turned 0.5 degrees | - | - | %.2e | %.2e | %s '
                    '(must be no) |' % (MAPPERS[m], control_rmse, control_largest,
                                        'no' if control_fails else 'YES'))
        notes.append('%s: %d of the %d pixels off by more than 0.01' % (
            MAPPERS[m], off, a.check_size ** 2) + (
            ', %d of them on the silhouette (an empty pixel of the reference beside them); '
            'the worst, %.4f, at pixel (%d, %d).' % (silhouette, worst[0], worst[1], worst[2])
            if off else '.'))
    text.append('| the exact reference | %.1f | %.0f | - | - | - |'
                % (ref['seconds'], ref['peak_mb'] * per))
    text += [''] + notes + ['']
    with open(os.path.join(a.output_dir, 'check.md'), 'w') as f:
        f.write('\n'.join(text))
    print('\n'.join(text))
    if passed:
        for kind in [k for m in mappers for k in (m, m + '-turned')] + ['reference']:
            if os.path.exists(path(kind)):
                os.remove(path(kind))  # (kept for a look when the check fails)
    return 0 if passed else 1


def worker(mapper_name, cubes, size):
    """One configuration; prints one JSON line."""
    import vtkhavs

    trim = ctypes.CDLL('libc.so.6').malloc_trim
    grid, mapper, volume = make_scene(mapper_name, cubes, size)
    tets = grid.GetNumberOfCells()
    trim(0)
    base = status_mb('VmRSS:')
    with open('/proc/self/clear_refs', 'w') as f:
        f.write('5')  # the peak resident size from here
    mapper.SetInputData(grid)
    window, renderer = make_window(volume, size)
    camera = set_camera(grid, renderer)

    def frame():
        t0 = time.time()
        window.Render()
        window.GetRGBACharPixelData(0, 0, 0, 0, 0)  # (waits for the frame)
        return time.time() - t0

    first = frame()
    if hasattr(mapper, 'GetLastMeshUpdate') and mapper.GetLastMeshUpdate() == 0:
        # Refused (vtkHAVSMapperBase::LargestGPUBuffer): nothing was drawn.
        print('HAVS_SCALE ' + json.dumps({
            'mapper': mapper_name, 'tets': tets, 'size': size,
            'skipped': 'refused with an error: a GPU buffer over LargestGPUBuffer (%d bytes)'
                       % mapper.GetLargestGPUBuffer()}), flush=True)
        return
    views = []
    for _ in range(3):
        camera.Azimuth(30)
        renderer.ResetCameraClippingRange()
        views.append(frame())
    views.sort()
    peak = status_mb('VmHWM:')
    trim(0)
    kept = status_mb('VmRSS:')
    row = {'mapper': mapper_name, 'tets': tets, 'size': size, 'first_s': first,
           'view_s': views[1], 'grid_mb': base, 'peak_mb': peak - base, 'kept_mb': kept - base,
           'renderer': vtkhavs.vtkHAVSRenderWindowFactory.GetBackendName(window),
           'smp': os.environ.get('VTK_SMP_BACKEND_IN_USE', 'Sequential')}
    if hasattr(mapper, 'GetMemoryBytes'):
        row['ledger_mb'] = mapper.GetMemoryBytes() / 1048576.0
        text = str(mapper)
        line = [l for l in text.split('\n') if l.strip().startswith('Memory:')]
        row['ledger'] = {name: int(b) for name, b in
                         re.findall(r' (.+?) (\d+) B;', line[0].strip()[len('Memory:'):])} \
            if line else {}
    print('HAVS_SCALE ' + json.dumps(row), flush=True)


def available_gb():
    with open('/proc/meminfo') as f:
        for line in f:
            if line.startswith('MemAvailable:'):
                return int(line.split()[1]) / 1048576.0
    return 0.0


def main():
    p = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    p.add_argument('--build', default='build')
    p.add_argument('--output-dir', default='Documentation/scale')
    p.add_argument('--sizes', default='1,5,10,25,50')
    p.add_argument('--mappers', default='havs,tetraycast,cellproj,pt')
    p.add_argument('--size', type=int, default=512)
    p.add_argument('--memory-limit-gb', type=float, default=0.0)
    p.add_argument('--check', type=float, default=0.0,
                   help='millions of tetrahedra: check HAVS there against the exact reference '
                        '(writes check.md) instead of the scale table')
    p.add_argument('--check-size', type=int, default=256)
    p.add_argument('--check-mappers', default='havs',
                   help='the mappers --check compares (havs, tetraycast, cellproj)')
    p.add_argument('--worker', nargs=3, metavar=('MAPPER', 'CUBES', 'SIZE'))
    p.add_argument('--check-worker', nargs=4, metavar=('KIND', 'CUBES', 'SIZE', 'OUT'))
    a = p.parse_args()
    if a.worker:
        worker(a.worker[0], int(a.worker[1]), int(a.worker[2]))
        return 0
    if a.check_worker:
        check_worker(a.check_worker[0], int(a.check_worker[1]), int(a.check_worker[2]),
                     a.check_worker[3])
        return 0

    build = os.path.abspath(a.build)
    env = dict(os.environ)
    pythonpath = [os.path.join(build, 'lib', d, 'dist-packages')
                  for d in os.listdir(os.path.join(build, 'lib')) if d.startswith('python3')]
    env['PYTHONPATH'] = os.pathsep.join(pythonpath + [env.get('PYTHONPATH', '')])
    env['LD_LIBRARY_PATH'] = os.path.join(build, 'lib')
    env['VTK_SMP_BACKEND_IN_USE'] = 'STDThread'
    fix = [f for f in os.listdir(os.path.join(build, 'lib')) if f.startswith('libvtkHAVSExpatFix')]
    if fix:
        env['LD_PRELOAD'] = os.path.join(build, 'lib', fix[0])
    limit = a.memory_limit_gb or max(1.0, available_gb() - 2.0)
    os.makedirs(a.output_dir, exist_ok=True)
    if a.check:
        return check(a, env)
    rows = []
    per_tet = {}  # mapper -> bytes a tetrahedron (peak + grid) at the largest size run
    for millions in [float(s) for s in a.sizes.split(',')]:
        cubes = cubes_for(millions)
        tets = 5 * cubes ** 3
        for m in a.mappers.split(','):
            if m in per_tet and per_tet[m] * tets / 2 ** 30 > limit:
                rows.append({'mapper': m, 'tets': tets, 'size': a.size,
                             'skipped': 'needs about %.1f GB (from %.0f B a tetrahedron '
                                        'measured at a smaller size), the limit is %.1f GB'
                                        % (per_tet[m] * tets / 2 ** 30, per_tet[m], limit)})
                print('%s %d: %s' % (m, tets, rows[-1]['skipped']), flush=True)
                continue
            t0 = time.time()
            r = subprocess.run([sys.executable, os.path.abspath(__file__), '--worker', m,
                                str(cubes), str(a.size)], env=env, capture_output=True, text=True)
            line = [l for l in r.stdout.split('\n') if l.startswith('HAVS_SCALE ')]
            if r.returncode != 0 or not line:
                rows.append({'mapper': m, 'tets': tets, 'size': a.size,
                             'skipped': 'failed (exit %d): %s' % (r.returncode,
                                                                 r.stderr.strip()[-300:])})
                print('%s %d: %s' % (m, tets, rows[-1]['skipped']), flush=True)
                continue
            row = json.loads(line[0][len('HAVS_SCALE '):])
            rows.append(row)
            if 'skipped' in row:
                print('%s %d: %s' % (m, tets, row['skipped']), flush=True)
                continue
            per_tet[m] = (row['peak_mb'] + row['grid_mb']) * 2 ** 20 / row['tets']
            print('%-10s %11d tets: first %6.2f s, new view %6.2f s, peak %6.0f B/tet, kept %6.0f '
                  'B/tet (%.0f s)' % (m, row['tets'], row['first_s'], row['view_s'],
                                       row['peak_mb'] * 2 ** 20 / row['tets'],
                                       row['kept_mb'] * 2 ** 20 / row['tets'], time.time() - t0),
                  flush=True)
    write(rows, a.output_dir)
    return 0


def write(rows, out):
    keys = ['mapper', 'tets', 'size', 'first_s', 'view_s', 'grid_mb', 'peak_mb', 'kept_mb',
            'ledger_mb', 'renderer', 'smp', 'skipped', 'ledger']
    with open(os.path.join(out, 'scale.csv'), 'w', newline='') as f:
        w = csv.writer(f)
        w.writerow(keys)
        for r in rows:
            w.writerow([json.dumps(r[k]) if k == 'ledger' and k in r else r.get(k, '')
                        for k in keys])
    lines = ['| tets | mapper | first image s | new view s | first / view | peak B/tet | '
             'kept B/tet | ledger B/tet |', '|---|---|---|---|---|---|---|---|']
    for r in rows:
        name = MAPPERS.get(r['mapper'], r['mapper'])
        if 'skipped' in r:
            lines.append('| %s | %s | not run: %s |||||||' % (format(r['tets'], ','), name,
                                                           r['skipped']))
            continue
        per = 2 ** 20 / r['tets']
        lines.append('| %s | %s | %.2f | %.2f | %.1f | %.0f | %.0f | %s |' % (
            format(r['tets'], ','), name, r['first_s'], r['view_s'], r['first_s'] / r['view_s'],
            r['peak_mb'] * per, r['kept_mb'] * per,
            '%.0f' % (r['ledger_mb'] * per) if 'ledger_mb' in r else '-'))
    parts = ['', 'The ledgers at the largest size run (bytes a tetrahedron):', '']
    largest = {}
    for r in rows:
        if 'ledger' in r:
            largest[r['mapper']] = r
    for m, r in largest.items():
        parts.append('- %s, %s tets: %s' % (MAPPERS[m], format(r['tets'], ','), '; '.join(
            '%s %.0f' % (k, v / r['tets']) for k, v in r['ledger'].items() if v > 0)))
    smp = sorted({r.get('smp', '') for r in rows if 'smp' in r})
    renderer = sorted({r.get('renderer', '') for r in rows if 'renderer' in r})
    head = ['# Scale: time and memory against mesh size', '',
            'Made by `python3 Apps/havs_scale.py` (%s; vtkSMPTools %s; window %s, %d^2). Memory '
            'is beyond the loaded grid: the peak resident size during the first image and the '
            'new views, and what is kept after them (after malloc_trim); the ledger is what the '
            "mapper's own arrays and GPU buffers hold (on llvmpipe the rasterizer's memory is in "
            'the process too, outside the ledger).' % (time.strftime('%Y-%m-%d'),
                                                       ', '.join(smp), ', '.join(renderer),
                                                       rows[0]['size'] if rows else 0), '']
    with open(os.path.join(out, 'scale.md'), 'w') as f:
        f.write('\n'.join(head + lines + parts) + '\n')
    try:
        import matplotlib
        matplotlib.use('Agg')
        import matplotlib.pyplot as plt
    except ImportError:
        print('havs_scale: matplotlib is not installed: no scale.png')
        return
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.5))
    for m in MAPPERS:
        rs = [r for r in rows if r['mapper'] == m and 'skipped' not in r]
        if not rs:
            continue
        x = [r['tets'] / 1e6 for r in rs]
        axes[0].plot(x, [r['first_s'] for r in rs], 'o-', label=MAPPERS[m])
        axes[1].plot(x, [r['view_s'] for r in rs], 'o-', label=MAPPERS[m])
        axes[2].plot(x, [r['peak_mb'] * 2 ** 20 / r['tets'] for r in rs], 'o-', label=MAPPERS[m])
    for ax, title in zip(axes, ['first image (s)', 'new view (s)', 'peak bytes a tetrahedron']):
        ax.set_xlabel('million tetrahedra')
        ax.set_title(title)
        ax.set_xscale('log')
        ax.grid(True, alpha=0.3)
    axes[0].set_yscale('log')
    axes[1].set_yscale('log')
    axes[2].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, 'scale.png'), dpi=90)


if __name__ == '__main__':
    sys.exit(main())
