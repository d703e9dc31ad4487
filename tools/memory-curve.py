#!/usr/bin/env python3
"""The studio's memory over time (docs/performance.md): runs `fatek-studio --demo` offscreen with
its own empty settings, samples its resident memory (VmRSS) at a fixed interval, and writes the
samples as CSV and the curve as SVG. Prints the figures the performance issue asks for: RSS at
start, the highest RSS, and the slope over the run's second half (MB per hour).

  tools/memory-curve.py build/release/app/fatek-studio/fatek-studio \\
      --minutes 120 --every 30 --csv memory.csv --svg docs/images/memory-demo.svg
  tools/memory-curve.py STUDIO --plot-only --csv memory.csv --compare before.csv --svg out.svg
"""

import argparse
import csv
import os
import signal
import subprocess
import sys
import tempfile
import time


def rss_mb(pid):
    with open(f"/proc/{pid}/status", encoding="ascii") as status:
        for line in status:
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) / 1024.0
    raise RuntimeError("no VmRSS")


def slope_per_hour(samples):
    """Least-squares slope of (minutes, MB), in MB per hour."""
    n = len(samples)
    if n < 2:
        return 0.0
    mx = sum(t for t, _ in samples) / n
    my = sum(m for _, m in samples) / n
    sxx = sum((t - mx) ** 2 for t, _ in samples)
    if sxx == 0:
        return 0.0
    sxy = sum((t - mx) * (m - my) for t, m in samples)
    return sxy / sxx * 60.0


def write_svg(path, curves, title):
    """curves: [(label, [(minutes, MB), ...], colour)], drawn on one pair of axes."""
    width, height = 720, 360
    left, right, top, bottom = 64, 24, 40, 48
    everything = [point for _, samples, _ in curves for point in samples]
    t_max = max(max(t for t, _ in everything), 1.0)
    m_max = max(m for _, m in everything)
    m_top = (int(m_max / 20) + 1) * 20
    plot_w, plot_h = width - left - right, height - top - bottom

    def x(t):
        return left + t / t_max * plot_w

    def y(m):
        return top + plot_h - m / m_top * plot_h

    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
           f'font-family="sans-serif" font-size="12">',
           f'<rect width="{width}" height="{height}" fill="white"/>',
           f'<text x="{width / 2}" y="22" text-anchor="middle" font-size="14">{title}</text>']
    for m in range(0, m_top + 1, 20):
        out.append(f'<line x1="{left}" y1="{y(m):.1f}" x2="{left + plot_w}" y2="{y(m):.1f}" '
                   f'stroke="#ddd"/>')
        out.append(f'<text x="{left - 6}" y="{y(m) + 4:.1f}" text-anchor="end">{m}</text>')
    step = 10 if t_max <= 60 else 20 if t_max <= 150 else 60
    for t in range(0, int(t_max) + 1, step):
        out.append(f'<line x1="{x(t):.1f}" y1="{top}" x2="{x(t):.1f}" y2="{top + plot_h}" '
                   f'stroke="#eee"/>')
        out.append(f'<text x="{x(t):.1f}" y="{top + plot_h + 16}" text-anchor="middle">{t}</text>')
    out.append(f'<text x="{left + plot_w / 2}" y="{height - 10}" text-anchor="middle">'
               'minutes</text>')
    out.append(f'<text x="16" y="{top + plot_h / 2}" text-anchor="middle" '
               f'transform="rotate(-90 16 {top + plot_h / 2})">RSS (MB)</text>')
    for i, (label, samples, colour) in enumerate(curves):
        points = " ".join(f"{x(t):.1f},{y(m):.1f}" for t, m in samples)
        out.append(f'<polyline points="{points}" fill="none" stroke="{colour}" '
                   'stroke-width="2"/>')
        ly = top + plot_h - 14 - 18 * (len(curves) - 1 - i)
        out.append(f'<line x1="{left + 12}" y1="{ly - 4}" x2="{left + 36}" '
                   f'y2="{ly - 4}" stroke="{colour}" stroke-width="2"/>')
        out.append(f'<text x="{left + 42}" y="{ly}">{label}</text>')
    out.append(f'<rect x="{left}" y="{top}" width="{plot_w}" height="{plot_h}" fill="none" '
               'stroke="#888"/>')
    out.append("</svg>")
    with open(path, "w", encoding="utf-8") as f:
        f.write("\n".join(out) + "\n")


def read_csv(path):
    with open(path, encoding="ascii") as f:
        return [(float(r["minutes"]), float(r["rss_mb"])) for r in csv.DictReader(f)]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("studio", help="the fatek-studio binary")
    parser.add_argument("--minutes", type=float, default=120)
    parser.add_argument("--every", type=float, default=30, help="seconds between samples")
    parser.add_argument("--csv", required=True)
    parser.add_argument("--svg")
    parser.add_argument("--label", default="this build")
    parser.add_argument("--compare", metavar="CSV",
                        help="an earlier run's samples, drawn beside this one's")
    parser.add_argument("--compare-label", default="before")
    parser.add_argument("--plot-only", action="store_true",
                        help="draw --svg from --csv (an earlier run's samples) without running")
    args = parser.parse_args()
    if args.plot_only:
        samples = read_csv(args.csv)
        plot(args, samples)
        return

    home = tempfile.mkdtemp(prefix="fatek-memory-")
    env = dict(os.environ, HOME=home, XDG_CONFIG_HOME=os.path.join(home, ".config"),
               XDG_DATA_HOME=os.path.join(home, ".local/share"), QT_QPA_PLATFORM="offscreen")
    app = subprocess.Popen([args.studio, "--demo"], env=env, stdout=subprocess.DEVNULL,
                           stderr=subprocess.DEVNULL)
    samples = []
    start = time.monotonic()
    time.sleep(min(5.0, args.every))  # the first sample after start-up, not during it
    try:
        while True:
            elapsed = time.monotonic() - start
            if app.poll() is not None:
                sys.exit(f"fatek-studio ended after {elapsed:.0f} s (exit {app.returncode})")
            samples.append((elapsed / 60.0, rss_mb(app.pid)))
            with open(args.csv, "w", newline="", encoding="ascii") as f:
                w = csv.writer(f)
                w.writerow(["minutes", "rss_mb"])
                w.writerows((f"{t:.2f}", f"{m:.1f}") for t, m in samples)
            if elapsed >= args.minutes * 60:
                break
            time.sleep(max(0.0, start + len(samples) * args.every - time.monotonic()))
    finally:
        if app.poll() is None:
            app.send_signal(signal.SIGTERM)
            try:
                app.wait(10)
            except subprocess.TimeoutExpired:
                app.kill()
    second_half = [s for s in samples if s[0] >= samples[-1][0] / 2]
    figures = (f"RSS at start {samples[0][1]:.1f} MB, highest {max(m for _, m in samples):.1f} MB, "
               f"last {samples[-1][1]:.1f} MB after {samples[-1][0]:.0f} min; "
               f"slope over the second half {slope_per_hour(second_half):+.2f} MB/h")
    print(figures)
    plot(args, samples)


def plot(args, samples):
    if not args.svg:
        return
    curves = [(args.label, samples, "#1f6fb2")]
    if args.compare:
        curves.insert(0, (args.compare_label, read_csv(args.compare), "#c0392b"))
    write_svg(args.svg, curves,
              f"fatek-studio --demo, resident memory ({samples[-1][0]:.0f} min, "
              f"every {args.every:.0f} s)")


if __name__ == "__main__":
    main()
