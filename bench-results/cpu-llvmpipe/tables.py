#!/usr/bin/env python3
"""The README's CPU tables as Markdown, from the CSV files run.sh wrote next to this script.

Usage: bench-results/cpu-llvmpipe/tables.py [FOLDER]   (default: this script's folder)
"""
import csv
import pathlib
import sys

folder = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).parent)


def rows(name):
    path = folder / name
    if not path.exists():
        return {}
    with path.open(newline="") as f:
        return {row.get("scene", str(i)) + ("" if "sessions" not in row else f"/{row['sessions']}/{row['width']}x{row['height']}"): row
                for i, row in enumerate(csv.DictReader(f))}


def num(value, digits=1):
    if value in (None, "", "nan"):
        return "–"
    number = float(value)
    return f"{number:,.{digits}f}".replace(",", " ")


def short(value):
    """A point error: three significant digits, scientific below a thousandth."""
    if value in (None, ""):
        return "–"
    number = float(value)
    return f"{number:.1e}" if 0 < number < 1e-3 else f"{number:.3g}"


def table(header, body):
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(cells) + " |" for cells in body]
    return "\n".join(lines)


def plan(row):
    parts, cast = int(row["mirror_parts"]), int(row["ray_cast_parts"])
    if parts == cast:
        return f"ray-cast ({parts} part{'s' if parts != 1 else ''})"
    return f"{cast} of {parts} parts ray-cast"


def ratio(numerator, denominator):
    return num(float(numerator) / float(denominator), 2) if denominator not in ("", "0") else "–"


default, searched, everything = rows("bench.csv"), rows("bench-searched.csv"), rows("bench-everything.csv")
name = lambda scene: pathlib.Path(scene).name

print(table(
    ["scene", "plan", "frame ms", "fps", "first ms", "raster floor ms", "floor + G-buffer × trace",
     "PSNR dB / SSIM / mirror mismatch (4 samples)", "ray trace ms", "× trace",
     "searched (`--ray-cast never`): frame ms / steps warm/cold / point error p99 px / mismatch / × trace",
     "`--plan everything` (20 frames): frame ms / × trace"],
    [[name(scene), plan(row), num(row["frame_ms_median"]), num(row["fps"]), num(row["first_frame_ms"], 0),
      num(row["raster_floor_ms"]),
      ratio(float(row["raster_floor_ms"]) + float(row.get("mirror-gbuffer_ms") or 0), row["raytrace_ms"]),
      f"{num(row['psnr_db'])} / {num(row['ssim'], 3)} / {num(row['mirror_mismatch'], 3)}", num(row["raytrace_ms"], 0),
      num(row["frame_vs_raytrace"], 2),
      (lambda s: f"{num(s['frame_ms_median'])} / {num(s['steps_warm_mean'])}/{num(s['steps_cold_mean'])} / "
                 f"{short(s['point_error_p99_px'])} / {num(s['mirror_mismatch'], 3)} / {num(s['frame_vs_raytrace'], 2)}")(
          searched[scene]) if scene in searched else "–",
      f"{num(everything[scene]['frame_ms_median'])} / {ratio(everything[scene]['frame_ms_median'], row['raytrace_ms'])}"
      if scene in everything else "–"]
     for scene, row in default.items()]))
print()

fixed = ["scene", "mirror-gbuffer", "gbuffer-pyramid", "ray-hierarchy", "search", "tessellation", "virtual-objects", "readback"]


def passes(row):
    return ", ".join(f"{key[:-3]} {num(value)}" for key, value in row.items()
                     if key.endswith("_ms") and key[:-3] in fixed and value not in ("", None))


print(table(["scene", "passes, default (median ms)", "passes, searched (median ms)"],
            [[name(scene), passes(row), passes(searched[scene]) if scene in searched else "–"]
             for scene, row in default.items()]))
print()

print(table(["scene", "still frame ms at 1 / 4 / 8 samples", "ray trace ms at 1 / 4 rays", "4 samples ÷ 1", "8 samples ÷ 1"],
            [[name(scene), f"{num(row['still_ms_1_samples'])} / {num(row['still_ms_4_samples'])} / {num(row['still_ms_8_samples'])}",
              f"{num(row['raytrace_ms'], 0)} / {num(row['raytrace_still_ms'], 0)}",
              ratio(row["still_ms_4_samples"], row["still_ms_1_samples"]),
              ratio(row["still_ms_8_samples"], row["still_ms_1_samples"])]
             for scene, row in default.items()]))
print()

print(table(["scene", "crosshair ms / steps mean / max", "hierarchy ms / steps mean / max",
             "explosion map ms / look-ups mean / max"],
            [[name(scene)] + [f"{num(row[f'{s}_search_ms'])} / {num(row[f'{s}_steps_mean'])} / {row[f'{s}_steps_max'] or '–'}"
                              for s in ("crosshair", "hierarchy", "explosion_map")]
             for scene, row in default.items()]))
print()

for file, title in (("serve.csv", "bench serve"), ("serve-instances.csv", "bench serve --instances 3")):
    serve = rows(file)
    if not serve:
        continue
    print(f"{title}:")
    print(table(["sessions", "size", "fps per session (min)", "latency p50 / p99 ms", "2 frame intervals ms", "render ms",
                 "encode ms", "KB/frame", "errors"],
                [[row["sessions"], f"{row['width']}×{row['height']}",
                  f"{num(row['fps_per_session_mean'])} ({num(row['fps_per_session_min'])})",
                  f"{num(row['latency_ms_p50'])} / {num(row['latency_ms_p99'])}", num(row["two_frame_intervals_ms"]),
                  num(row["render_ms_mean"]), num(row["encode_ms_mean"], 2), num(float(row["bytes_per_frame"]) / 1024),
                  row["errors"]]
                 for row in serve.values()]))
    print()
