# SPDX-License-Identifier: GPL-3.0-or-later
"""The soak test's checks, from the job's G-code and the firmware's motor step traces.

Everything is compared in joint space (X/Y of the job are the motor angles in degrees; GRBL moves
joint-linearly, so every pen-down step sample lies within a step or two of the G-code's joint
polyline). A stroke is the run of pen-down motion lines between a pen-down and a pen-up command.
  missing     a pen-down segment (G-code line) some point of which (1/4, 1/2, 3/4) no pen-down
              trace stretch comes near
  duplicated  a segment whose midpoint is drawn by more pen-down passes (a pass: the pen down
              once, until it lifts) than 1 + the fault seams it lies in (a seam: the lines after
              a fault's resume point up to the last line sent before the fault)
  stray       pen-down trace samples farther than the tolerance from every pen-down segment
Python 3 standard library only.
"""
import math
import re

from wire import compact

TOL_DEG = 0.07    # 2.5 motor steps of the maker-plotter (35.5556 steps/deg)
CELL_DEG = 0.25


def parse_job(path):
    """-> (sendable [(fileLine, text)], segments [(fileLine, stroke, (x0, y0), (x1, y1))],
    start pose (deg))."""
    sendable, segments = [], []
    pos, start = None, None
    pen, stroke = False, -1
    word = re.compile(r'([A-Z])(-?[0-9.]+)')
    with open(path) as f:
        for n, raw in enumerate(f, 1):
            m = re.search(r'start pose X(-?[0-9.]+) Y(-?[0-9.]+)', raw)
            if m and start is None:
                start = (float(m.group(1)), float(m.group(2)))
                pos = start
            text = compact(raw)
            if not text:
                continue
            sendable.append((n, text))
            words = dict()
            codes = []
            for letter, value in word.findall(text):
                if letter in 'GM':
                    codes.append(letter + str(int(float(value))))
                else:
                    words[letter] = float(value)
            if 'M5' in codes or 'M2' in codes or 'M30' in codes:
                pen = False
            if 'M3' in codes or 'M4' in codes:
                now = words.get('S', 1.0) > 0
                if now and not pen:
                    stroke += 1
                pen = now
            if ('X' in words or 'Y' in words) and 'G4' not in codes:
                new = (words.get('X', pos[0]), words.get('Y', pos[1]))
                if pen and new != pos:
                    segments.append((n, stroke, pos, new))
                pos = new
    return sendable, segments, start


def read_trace(path, home, steps_per_deg):
    """-> list of (x, y, pen) in work degrees, one per sample."""
    out = []
    with open(path) as f:
        for line in f:
            if not line.strip() or line.startswith('#'):
                continue
            parts = line.replace(',', ' ').split()
            if len(parts) < 5:
                continue
            s1, s2, spindle = int(parts[1]), int(parts[2]), int(parts[4])
            out.append((home[0] + s1 / steps_per_deg, home[1] + s2 / steps_per_deg, spindle != 0))
    return out


def seg_dist(p, a, b):
    ax, ay = a
    dx, dy = b[0] - ax, b[1] - ay
    L = dx * dx + dy * dy
    u = 0.0 if L == 0 else max(0.0, min(1.0, ((p[0] - ax) * dx + (p[1] - ay) * dy) / L))
    return math.hypot(p[0] - ax - u * dx, p[1] - ay - u * dy)


class Grid:
    def __init__(self):
        self.cells = {}

    def add(self, a, b, item):
        x0, x1 = sorted((a[0], b[0]))
        y0, y1 = sorted((a[1], b[1]))
        for i in range(int(math.floor((x0 - TOL_DEG) / CELL_DEG)), int(math.floor((x1 + TOL_DEG) / CELL_DEG)) + 1):
            for j in range(int(math.floor((y0 - TOL_DEG) / CELL_DEG)), int(math.floor((y1 + TOL_DEG) / CELL_DEG)) + 1):
                self.cells.setdefault((i, j), []).append(item)

    def near(self, p):
        return self.cells.get((int(math.floor(p[0] / CELL_DEG)), int(math.floor(p[1] / CELL_DEG))), ())


def pen_passes(traces):
    """Pen-down stretches from sample i (pen down) to sample i+1, with a pass id each."""
    stretches, passes = [], 0
    for samples in traces:
        down = False
        for i in range(len(samples) - 1):
            x, y, pen = samples[i]
            if pen and not down:
                passes += 1
            down = pen
            if pen:
                stretches.append(((x, y), samples[i + 1][:2], passes))
    return stretches, passes


def check(job_path, trace_paths, home, steps_per_deg, seams):
    """seams: [(after_line, up_to_line)] file lines. -> dict of counts and examples."""
    _, segments, _ = parse_job(job_path)
    traces = [read_trace(p, home, steps_per_deg) for p in trace_paths]
    stretches, passes = pen_passes(traces)
    ink = Grid()
    for k, (a, b, _) in enumerate(stretches):
        ink.add(a, b, k)

    def passes_at(p):
        return {stretches[k][2] for k in ink.near(p) if seg_dist(p, stretches[k][0], stretches[k][1]) <= TOL_DEG}

    missing, duplicated, in_seams = [], [], 0
    per_seam = [0] * len(seams)
    strokes_missing, strokes_dup, strokes = set(), set(), set()
    for line, stroke, a, b in segments:
        strokes.add(stroke)
        pts = [(a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1])) for f in (0.25, 0.5, 0.75)]
        counts = [len(passes_at(p)) for p in pts]
        if min(counts) == 0:
            missing.append(line)
            strokes_missing.add(stroke)
            continue
        allowed = 1 + sum(1 for lo, hi in seams if lo < line <= hi)
        if 1 < counts[1] <= allowed:
            in_seams += 1
            for k, (lo, hi) in enumerate(seams):
                if lo < line <= hi:
                    per_seam[k] += 1
        if counts[1] > allowed:
            duplicated.append(line)
            strokes_dup.add(stroke)

    drawn = Grid()
    for k, (_, _, a, b) in enumerate(segments):
        drawn.add(a, b, k)
    stray, last = 0, None
    for a, b, _ in stretches:
        if a == last:
            continue
        last = a
        if not any(seg_dist(a, segments[k][2], segments[k][3]) <= TOL_DEG for k in drawn.near(a)):
            stray += 1
    return {
        'segments': len(segments), 'strokes': len(strokes), 'passes': passes,
        'pen_down_samples': len(stretches),
        'missing_segments': len(missing), 'missing_strokes': len(strokes_missing),
        'duplicated_segments': len(duplicated), 'duplicated_strokes': len(strokes_dup),
        'redrawn_in_seams': in_seams, 'redrawn_per_seam': per_seam, 'stray_samples': stray,
        'missing_lines': missing[:10], 'duplicated_lines': duplicated[:10],
    }


def wire_intact(sent, byte_logs):
    """Every line the proxy forwarded reached the firmware, in order (grbl-sim's -L logs, RX):
    -> (lines forwarded, lines the firmware received, forwarded lines missing there)."""
    import codecs
    rx = []
    for path in byte_logs:
        chunk = ''
        with open(path) as f:
            for record in f:
                parts = record.split(' ', 3)
                if len(parts) == 4 and parts[3].startswith('RX '):
                    chunk += codecs.decode(parts[3][3:].rstrip('\n'), 'unicode_escape')
        chunk = re.sub('[?!~\x18\x80-\xff]', '', chunk).replace('\r', '\n')
        rx += [x for x in chunk.split('\n') if x]
    sent = [x for x in sent if x]
    i = 0
    for line in rx:
        if i < len(sent) and (line == sent[i] or (line.startswith('*') and line[1:] == sent[i][1:])):
            i += 1
    return len(sent), len(rx), len(sent) - i
