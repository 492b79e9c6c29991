"""``camtool exif --exiftool`` against ExifTool itself: every composite it derives, within 1 %.

Two references, both independent of camtool:

- ExifTool 12.57's composites recorded for the exiv2 project's real camera files
  (../shared/reference/exif-samples/exiftool-composite.json, made with
  ``exiftool -j -n -G0 -Composite:all``; see that folder's README); skipped
  when the folder is absent;
- ``exiftool -j -n -Composite:all`` run now on those files and on the test
  images of tests/data/exif (made by make_images.py there); skipped when
  ``exiftool`` is not installed (``.ci/run`` installs Debian's
  libimage-exiftool-perl), and on the maker-note files of
  tests/test_exif_makers.py (Canon ShotInfo, Nikon, Olympus, Minolta, Casio).

A composite ExifTool gives and camtool does not is a disagreement; one camtool
gives and ExifTool does not is not counted (camtool's own mode goes further on
purpose). DOF counts once (near and far both within 1 %, ExifTool's far 0 being
infinity) and so does FOV (the angle, and the field width at the focus
distance when ExifTool gives one).
"""

from __future__ import annotations

import json
import math
import shutil
import subprocess
from collections.abc import Iterator, Mapping
from pathlib import Path
from typing import Any

import pytest

from tests.cli_helpers import run

pytest.importorskip("exiv2")

DATA = Path(__file__).resolve().parent / "data" / "exif"
SAMPLES = Path(__file__).resolve().parent.parent.parent / "shared" / "reference" / "exif-samples"
CAMERA = sorted((SAMPLES / "camera").glob("*")) if (SAMPLES / "camera").is_dir() else []
RECORDED = SAMPLES / "exiftool-composite.json"
OURS = [DATA / name for name in ("canon_bracket.jpg", "canon_infinity.jpg", "nikon.jpg", "olympus.jpg",
                                 "fujifilm_subject.jpg", "sony_apex_lens.jpg", "resized_high_iso.jpg",
                                 "canon_shotinfo.jpg", "partial.jpg")]
TOLERANCE = 0.01


def _close(mine: float | None, theirs: float) -> bool:
    if mine is None or not math.isfinite(mine):
        return False
    return mine == theirs or abs(mine - theirs) <= TOLERANCE * abs(theirs)


def _numbers(value: Any) -> list[float]:
    return [float(part) for part in str(value).split()]


def comparisons(row: Mapping[str, Any], composite: Mapping[str, Any]) -> Iterator[tuple[str, bool, str]]:
    """(composite name, agrees, what each side says) for every composite ExifTool gives that camtool derives."""
    tags = {key.removeprefix("Composite:"): value for key, value in composite.items()}

    def mm_to_m(value: float | None) -> float | None:
        return None if value is None else value / 1000.0

    if "ScaleFactor35efl" in tags:
        theirs = float(tags["ScaleFactor35efl"])
        yield "ScaleFactor35efl", _close(row["crop_factor"], theirs), f"{row['crop_factor']} vs {theirs}"
    if "CircleOfConfusion" in tags:
        theirs = float(tags["CircleOfConfusion"])
        yield "CircleOfConfusion", _close(row["coc_mm"], theirs), f"{row['coc_mm']} vs {theirs}"
    if "HyperfocalDistance" in tags:
        theirs = float(tags["HyperfocalDistance"])
        mine = mm_to_m(row["hyperfocal_mm"])
        yield "HyperfocalDistance", _close(mine, theirs), f"{mine} vs {theirs}"
    if "DOF" in tags:
        near, far = _numbers(tags["DOF"])
        my_near = mm_to_m(row["near_mm"])
        # JSON writes an infinite far limit as null; ExifTool writes 0
        far_ok = (row["far_mm"] is None and my_near is not None) if far == 0 else _close(mm_to_m(row["far_mm"]), far)
        yield "DOF", _close(my_near, near) and far_ok, f"{my_near} {mm_to_m(row['far_mm'])} vs {near} {far}"
    if "FOV" in tags:
        angle, *width = _numbers(tags["FOV"])
        ok = _close(row["horizontal_deg"], angle) and (not width or _close(mm_to_m(row["field_width_mm"]), width[0]))
        yield "FOV", ok, f"{row['horizontal_deg']} {mm_to_m(row['field_width_mm'])} vs {tags['FOV']}"
    if "LightValue" in tags:
        theirs = float(tags["LightValue"])
        yield "LightValue", _close(row["ev100"], theirs), f"{row['ev100']} vs {theirs}"


def camtool_rows(paths: list[Path]) -> dict[str, dict[str, Any]]:
    result = run("exif", "--exiftool", "--format", "json", *map(str, paths))
    assert result.exit_code in (0, 1), result.output
    return {row["file"]: row for row in json.loads(result.stdout)}


def agreement(rows: Mapping[str, Mapping[str, Any]],
              composites: Mapping[str, Mapping[str, Any]]) -> tuple[int, list[str]]:
    """The number of comparisons and the ones that disagree (one line each)."""
    total, wrong = 0, []
    for path, composite in composites.items():
        for name, ok, shown in comparisons(rows[path], composite):
            total += 1
            if not ok:
                wrong.append(f"{Path(path).name} {name}: camtool {shown} (ExifTool)")
    return total, wrong


def test_comparisons_fail_on_a_wrong_value() -> None:
    row = {"crop_factor": 1.5, "coc_mm": 0.02, "hyperfocal_mm": 10000.0, "near_mm": 2000.0, "far_mm": None,
           "horizontal_deg": 40.0, "field_width_mm": 1000.0, "ev100": 10.0}
    good = {"ScaleFactor35efl": 1.505, "CircleOfConfusion": 0.0201, "HyperfocalDistance": 10.05, "DOF": "2.01 0",
            "FOV": "40.2 1.005", "LightValue": 10.05}
    assert all(ok for _, ok, _ in comparisons(row, good))
    for key, bad in (("ScaleFactor35efl", 1.52), ("DOF", "2.01 50"), ("FOV", "40.2 1.2"), ("LightValue", 10.2)):
        assert not all(ok for _, ok, _ in comparisons(row, {**good, key: bad})), key
    assert not all(ok for _, ok, _ in comparisons({**row, "ev100": None}, good))


@pytest.mark.skipif(not RECORDED.is_file(), reason="../shared/reference/exif-samples is absent")
def test_recorded_exiftool_composites_of_real_camera_files() -> None:
    recorded = json.loads(RECORDED.read_text())
    composites = {str(SAMPLES / entry["SourceFile"]): entry for entry in recorded}
    rows = camtool_rows([Path(path) for path in composites])
    total, wrong = agreement(rows, composites)
    assert total >= 80  # the 20 files give 80 comparisons
    assert not wrong, f"{total - len(wrong)} of {total} agree:\n" + "\n".join(wrong)


@pytest.mark.skipif(shutil.which("exiftool") is None, reason="exiftool is not installed")
def test_live_exiftool_on_camera_files_and_test_images(tmp_path: Path) -> None:
    from tests.test_exif_makers import maker_files

    paths = [*CAMERA, *OURS, *maker_files(tmp_path)]
    output = subprocess.run(["exiftool", "-j", "-n", "-Composite:all", *map(str, paths)], capture_output=True,
                            text=True, timeout=300, check=False).stdout
    composites = {entry["SourceFile"]: entry for entry in json.loads(output)}
    rows = camtool_rows(paths)
    total, wrong = agreement(rows, composites)
    assert total >= 20
    assert not wrong, f"{total - len(wrong)} of {total} agree:\n" + "\n".join(wrong)
