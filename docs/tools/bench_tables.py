#!/usr/bin/env python3
"""The documentation's benchmark tables, generated from the CSV files under bench-results/.

Each table sits in README.md or a page of docs/ between `<!-- generated:NAME begin -->` and
`<!-- generated:NAME end -->`; NAME is one of TABLES below.

Usage: docs/tools/bench_tables.py            rewrite every generated section in place
       docs/tools/bench_tables.py --check    name the stale sections and exit 1 if there are any
"""
import argparse
import csv
import pathlib
import re
import sys

REPOSITORY = pathlib.Path(__file__).resolve().parents[2]
SECTION = re.compile(r"(<!-- generated:(?P<name>[\w.-]+) begin -->\n)(?P<body>.*?)(<!-- generated:(?P=name) end -->)",
                     re.DOTALL)


def read_rows(path):
    """The CSV's rows in file order; none when the file is missing."""
    if not path.exists():
        return []
    with path.open(newline="") as f:
        return list(csv.DictReader(f))


def by_scene(rows):
    return {row["scene"]: row for row in rows}


def num(value, digits=1):
    if value in (None, "", "nan"):
        return "–"
    return f"{float(value):,.{digits}f}".replace(",", " ")


def short(value):
    """A point error: three significant digits, scientific below a thousandth."""
    if value in (None, ""):
        return "–"
    number = float(value)
    return f"{number:.1e}" if 0 < number < 1e-3 else f"{number:.3g}"


def ratio(numerator, denominator):
    return num(float(numerator) / float(denominator), 2) if denominator not in ("", "0") else "–"


def table(header, body):
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(cells) + " |" for cells in body]
    return "\n".join(lines)


def plan(row):
    parts, cast = int(row["mirror_parts"]), int(row["ray_cast_parts"])
    count = f"{parts} part{'s' if parts != 1 else ''}"
    if parts == cast:
        return f"ray-cast ({count})"
    if cast == 0:
        return f"searched ({count})"
    return f"{cast} of {count} ray-cast"


def scene_name(scene):
    """A glTF or JSON scene by its file name without folders."""
    return pathlib.Path(scene).name


class Results:
    """The CSV files of one checkout's bench-results/."""

    def __init__(self, folder):
        self.folder = folder

    def rows(self, name):
        return read_rows(self.folder / name)

    def cpu(self, name):
        return self.rows(f"cpu-llvmpipe/{name}")


def cpu_default(results):
    default = results.cpu("bench.csv")
    searched, everything = by_scene(results.cpu("bench-searched.csv")), by_scene(results.cpu("bench-everything.csv"))

    def searched_cells(row):
        return (f"{num(row['frame_ms_median'])} / {num(row['steps_warm_mean'])}/{num(row['steps_cold_mean'])} / "
                f"{short(row['point_error_p99_px'])} / {num(row['mirror_mismatch'], 3)} / {num(row['frame_vs_raytrace'], 2)}")

    return table(
        ["scene", "plan", "frame ms", "fps", "first ms", "raster floor ms", "floor + G-buffer × trace",
         "PSNR dB / SSIM / mirror mismatch (4 samples)", "ray trace ms", "× trace",
         "searched (`--ray-cast never`): frame ms / steps warm/cold / point error p99 px / mismatch / × trace",
         "`--plan everything` (20 frames): frame ms / × trace"],
        [[scene_name(row["scene"]), plan(row), num(row["frame_ms_median"]), num(row["fps"]), num(row["first_frame_ms"], 0),
          num(row["raster_floor_ms"]),
          ratio(float(row["raster_floor_ms"]) + float(row.get("mirror-gbuffer_ms") or 0), row["raytrace_ms"]),
          f"{num(row['psnr_db'])} / {num(row['ssim'], 3)} / {num(row['mirror_mismatch'], 3)}", num(row["raytrace_ms"], 0),
          num(row["frame_vs_raytrace"], 2),
          searched_cells(searched[row["scene"]]) if row["scene"] in searched else "–",
          f"{num(everything[row['scene']]['frame_ms_median'])} / "
          f"{ratio(everything[row['scene']]['frame_ms_median'], row['raytrace_ms'])}" if row["scene"] in everything else "–"]
         for row in default])


PASSES = ["scene", "mirror-gbuffer", "gbuffer-pyramid", "ray-hierarchy", "search", "tessellation", "virtual-objects",
          "readback"]


def pass_times(row):
    return ", ".join(f"{key[:-3]} {num(value)}" for key, value in row.items()
                     if key.endswith("_ms") and key[:-3] in PASSES and value not in ("", None))


def cpu_passes(results):
    searched = by_scene(results.cpu("bench-searched.csv"))
    return table(["scene", "passes, default (median ms)", "passes, searched (median ms)"],
                 [[scene_name(row["scene"]), pass_times(row),
                   pass_times(searched[row["scene"]]) if row["scene"] in searched else "–"]
                  for row in results.cpu("bench.csv")])


def cpu_stills(results):
    return table(["scene", "still frame ms at 1 / 4 / 8 samples", "ray trace ms at 1 / 4 rays", "4 samples ÷ 1",
                  "8 samples ÷ 1"],
                 [[scene_name(row["scene"]),
                   f"{num(row['still_ms_1_samples'])} / {num(row['still_ms_4_samples'])} / {num(row['still_ms_8_samples'])}",
                   f"{num(row['raytrace_ms'], 0)} / {num(row['raytrace_still_ms'], 0)}",
                   ratio(row["still_ms_4_samples"], row["still_ms_1_samples"]),
                   ratio(row["still_ms_8_samples"], row["still_ms_1_samples"])]
                  for row in results.cpu("bench.csv")])


def cpu_searches(results):
    return table(["scene", "crosshair ms / steps mean / max", "hierarchy ms / steps mean / max",
                  "explosion map ms / look-ups mean / max"],
                 [[scene_name(row["scene"])] +
                  [f"{num(row[f'{s}_search_ms'])} / {num(row[f'{s}_steps_mean'])} / {row[f'{s}_steps_max'] or '–'}"
                   for s in ("crosshair", "hierarchy", "explosion_map")]
                  for row in results.cpu("bench.csv")])


def cpu_planner(results):
    """The planner on, on with every part searched, and off, on the scenes where it matters most."""
    runs = [("needed", "bench.csv"), ("needed, `--ray-cast never`", "bench-searched.csv"),
            ("everything (20 frames)", "bench-everything.csv")]
    body = []
    for scene in ("ants", "kitchen", "beads"):
        rows = [(planner, by_scene(results.cpu(file)).get(scene)) for planner, file in runs]
        body += [[scene if i == 0 else "", planner, num(row["frame_ms_median"]), num(row["mirror_mismatch"], 3), plan(row)]
                 for i, (planner, row) in enumerate((planner, row) for planner, row in rows if row)]
    return table(["scene", "planner", "frame ms", "mirror mismatch", "what the plan did"], body)


def serve(rows):
    return table(["sessions", "size", "fps per session (min)", "latency p50 / p99 ms", "2 frame intervals ms",
                  "render ms", "encode ms", "KB/frame", "errors"],
                 [[row["sessions"], f"{row['width']}×{row['height']}",
                   f"{num(row['fps_per_session_mean'])} ({num(row['fps_per_session_min'])})",
                   f"{num(row['latency_ms_p50'])} / {num(row['latency_ms_p99'])}", num(row["two_frame_intervals_ms"]),
                   num(row["render_ms_mean"]), num(row["encode_ms_mean"], 2), num(float(row["bytes_per_frame"]) / 1024),
                   row["errors"]]
                  for row in rows])


def gpu_h200(results):
    default = results.rows("gpu-h200/bench.csv")
    searched = by_scene(results.rows("gpu-h200/bench-searched.csv"))

    def searched_cells(row, trace_ms):
        return (f"{num(row['frame_ms_median'], 2)} / {num(row['steps_warm_mean'])}/{num(row['steps_cold_mean'])} / "
                f"{short(row['point_error_p99_px'])} / {ratio(row['frame_ms_median'], trace_ms)}")

    return table(["scene", "frame ms", "fps", "raster floor ms", "PSNR dB / SSIM / mirror mismatch",
                  "ray trace ms (16 cores)", "× trace", "searched: frame ms / steps warm/cold / point error p99 px / × trace"],
                 [[row["scene"], num(row["frame_ms_median"], 2), num(row["fps"], 0), num(row["raster_floor_ms"], 2),
                   f"{num(row['psnr_db'])} / {num(row['ssim'], 3)} / {num(row['mirror_mismatch'], 3)}",
                   num(row["raytrace_ms"]), num(row["frame_vs_raytrace"], 2),
                   searched_cells(searched[row["scene"]], row["raytrace_ms"]) if row["scene"] in searched else "–"]
                  for row in default])


def wave3_sizes(results):
    def planner(row):
        predicted, took = float(row["planner_predicted_ms"]), float(row["planner_took_ms"])
        return f"{num(predicted)} / {num(took)} ({(predicted / took - 1) * 100:+.0f} %)"

    return table(["scene", "size", "searched ms", "cast ms", "searched ÷ cast", "plan", "frame ms", "floor ms",
                  "frame ÷ floor", "planner predicted / took ms", "rates (search / cast)"],
                 [[row["scene"], f"{row['width']}×{row['height']}", num(row["searched_frame_ms"], 2),
                   num(row["cast_frame_ms"], 2), num(row["searched_over_cast"], 2), plan(row),
                   num(row["frame_ms_median"], 2), num(row["raster_floor_ms"], 2),
                   ratio(row["frame_ms_median"], row["raster_floor_ms"]), planner(row),
                   f"{num(row['planner_rate_search'], 2)} / {num(row['planner_rate_cast'], 2)}"]
                  for row in results.rows("cpu-llvmpipe-wave3/bench-sizes.csv")])


def tessellation_rounds(results):
    return table(["scene", "searched ms, rounds read back (per pass)", "rounds on the GPU (per pass)",
                  "searched ms, whole frame", "cast ms, whole frame", "searched ÷ cast"],
                 [[row["scene"], num(row["before_searched_ms"], 2), num(row["after_searched_ms"], 2),
                   num(row["searched_frame_ms"], 2), num(row["cast_frame_ms"], 2), num(row["searched_over_cast"], 2)]
                  for row in results.rows("gpu-driven-tessellation/summary.csv")])


def accuracy(scene):
    """The bench's own accuracy report (its accuracy.md), from its CSV."""
    def build(results):
        def cell(value):
            return value if value != "" else "-"

        def row_cells(row):
            reference = row["family"] == "reference"
            setting = f"**{row['setting']}**" if row["pareto"] == "true" else row["setting"]
            errors = (f"{row['point_error_p99_px']} / {row['point_error_max_px']}"
                      if row["point_error_p99_px"] != "" else "-")
            return [setting, row["frame_ms_median"], row["psnr_db"], row["ssim"], row["mirror_mismatch"],
                    errors, "-" if reference else cell(row["drawn_vertices"]), "-" if reference else cell(row["searches"])]

        return table(["setting", "frame ms", "PSNR dB", "SSIM", "mirror mismatch", "point error p99 / max px",
                      "drawn vertices", "searches"],
                     [row_cells(row) for row in results.rows(f"accuracy/{scene}/accuracy.csv")])
    return build


TABLES = {
    "cpu-default": cpu_default,
    "cpu-passes": cpu_passes,
    "cpu-stills": cpu_stills,
    "cpu-searches": cpu_searches,
    "cpu-planner": cpu_planner,
    "cpu-serve": lambda results: serve(results.cpu("serve.csv")),
    "cpu-serve-instances": lambda results: serve(results.cpu("serve-instances.csv")),
    "gpu-h200": gpu_h200,
    "gpu-h200-serve": lambda results: serve(results.rows("gpu-h200/serve.csv")),
    "wave3-sizes": wave3_sizes,
    "tessellation-rounds": tessellation_rounds,
    **{f"accuracy-{scene}": accuracy(scene)
       for scene in ("checker-sphere", "teapot-table", "mesh-sphere", "kitchen", "cylinder")},
}


def pages(repository):
    return [repository / "README.md"] + sorted((repository / "docs").glob("*.md"))


def regenerated(text, results, where):
    """The text with every generated section rebuilt; a section of unknown name is an error naming it."""
    def rebuild(match):
        name = match["name"]
        if name not in TABLES:
            raise SystemExit(f"{where}: unknown generated section '{name}' (known: {', '.join(TABLES)})")
        return f"{match[1]}{TABLES[name](results)}\n{match[4]}"
    return SECTION.sub(rebuild, text)


def stale_sections(repository):
    """'page: section' for every generated section whose table differs from what bench-results/ gives now."""
    results = Results(repository / "bench-results")
    stale = []
    for page in pages(repository):
        text = page.read_text()
        for match in SECTION.finditer(text):
            if regenerated(match[0], results, page.name) != match[0]:
                stale.append(f"{page.relative_to(repository)}: {match['name']}")
    return stale


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--check", action="store_true", help="report stale sections instead of rewriting them")
    parser.add_argument("--repository", type=pathlib.Path, default=REPOSITORY, help="checkout root (default: this one)")
    args = parser.parse_args()
    if args.check:
        stale = stale_sections(args.repository)
        for section in stale:
            print(f"stale generated table {section}: run docs/tools/bench_tables.py", file=sys.stderr)
        return 1 if stale else 0
    results = Results(args.repository / "bench-results")
    for page in pages(args.repository):
        text = page.read_text()
        new_text = regenerated(text, results, page.name)
        if new_text != text:
            page.write_text(new_text)
            print(f"rewrote {page.relative_to(args.repository)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
