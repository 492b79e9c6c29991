"""Write the aberration tables of the shipped prescriptions: ``python -m camtool.dof.tables``.

A command with a shipped prescription needs its aberration table
(:func:`camtool.dof.auto.aberration_table`); computing one traces rays
(numpy and about 20 ms of tracing), so the tables of every prescription in
``lens_db/prescriptions/`` are computed once, here, and shipped beside
:mod:`camtool.dof.auto` as :data:`camtool.dof.auto.SHIPPED_TABLES`, each keyed
by the content digest of its prescription. Run this after changing a
shipped prescription or the table's computation (``tests/test_aberration_table.py``
fails until then); ``--check`` only says whether the shipped file is current.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
from typing import Any

from camtool.dof import auto


def shipped_prescriptions() -> list[tuple[str, Any]]:
    """``(file name, prescription)`` of every file in ``lens_db/prescriptions/``, in name order."""
    from camtool.optics.prescription import prescription_from_mapping
    from camtool.presets import paths
    from camtool.presets.loader import read_file

    directory = os.path.join(paths.shipped_dir(), "prescriptions")
    out = []
    for path in paths.yaml_files(directory, ()):
        for record in read_file(path).records.get("prescription", []):
            mapping = {key: value for key, value in record["_data"].items() if not str(key).startswith("_")}
            out.append((os.path.basename(path), prescription_from_mapping(mapping, source=record["id"])))
    return out


def document() -> dict[str, Any]:
    """The shipped file's content: every table, computed afresh, keyed by its prescription's source digest."""
    tables: dict[str, Any] = {}
    names: dict[str, str] = {}
    for name, prescription in shipped_prescriptions():
        source = auto._source(prescription)
        grid, rows = auto._compute_table(prescription)
        tables[source] = {"f_numbers": list(grid), "table": [[list(pair) for pair in row] for row in rows]}
        names[source] = name
    return {"version": auto._TABLE_VERSION, "prescriptions": names, "tables": tables}


def render(content: dict[str, Any]) -> str:
    """The file's text: JSON, one table a line (floats written as Python writes them, so they read back exactly)."""
    return json.dumps(content, indent=1, sort_keys=True, allow_nan=False) + "\n"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--check", action="store_true", help="exit 1 when the shipped file is not current")
    args = parser.parse_args(argv)
    target = os.path.join(os.path.dirname(os.path.abspath(auto.__file__)), auto.SHIPPED_TABLES)
    text = render(document())
    try:
        with open(target, encoding="utf-8") as handle:
            current = handle.read()
    except OSError:
        current = ""
    if args.check:
        print(f"{target}: {'current' if current == text else 'out of date'}")
        return 0 if current == text else 1
    with open(target, "w", encoding="utf-8") as handle:
        handle.write(text)
    print(f"wrote {target}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
