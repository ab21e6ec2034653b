#!/usr/bin/env python3
"""Side by side: the old and new binaries' bench rows (median frame ms per round; accuracy columns)."""
import csv
import sys
from pathlib import Path

out = Path(sys.argv[1])
columns = ["frame_ms_median", "mirror_mismatch", "psnr_db", "point_error_p99_px", "searched_per_frame", "steps_warm_mean"]


def rows(which, round_):
    with open(out / f"bench-{which}-{round_}.csv") as f:
        return {row["scene"]: row for row in csv.DictReader(f)}


runs = {(w, r): rows(w, r) for w in ("old", "new") for r in (1, 2)}
present = [c for c in columns if c in next(iter(runs[("old", 1)].values()))]
print("scene | " + " | ".join(f"{c} old 1/2 | new 1/2" for c in present))
for scene in runs[("old", 1)]:
    cells = []
    for c in present:
        cells.append(f"{runs[('old', 1)][scene][c]}/{runs[('old', 2)][scene][c]} | "
                     f"{runs[('new', 1)][scene][c]}/{runs[('new', 2)][scene][c]}")
    print(f"{scene} | " + " | ".join(cells))
