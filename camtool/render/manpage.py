"""Man pages rendered from click command definitions: ``camtool.1`` and one page per subcommand.

:func:`pages` takes the command group and returns each page's roff source;
it reads only what the commands declare (help texts, options, output keys),
so the pages follow the commands. The date is pinned (:data:`MAN_DATE`) so
that rendering is reproducible. ``python -m camtool.cli.manpage DIR`` writes
the pages of ``camtool`` itself.
"""

from __future__ import annotations

from pathlib import Path

import click

from camtool import __version__

MAN_DATE = "2026-11-22"
HELP_OPTIONS = ["-h", "--help"]

ENVIRONMENT = [
    ("CAMTOOL_FORMAT", "Default output format (table, json or csv) when --format is not given."),
    ("NO_COLOR", "When set (to anything), tables are printed without colour (colour is only used on a terminal "
                 "anyway); TERM=dumb does the same."),
    ("FORCE_COLOR", "When set, tables are coloured into a pipe too (for less -R)."),
    ("COLUMNS", "Width of the terminal for tables (ignored unless a positive number); columns that neither "
                "identify a row nor hold its answer are left out to fit and named on stderr, never cropped; "
                "text then wraps, and a table still too wide becomes one block per row; into a pipe a table takes "
                "the width it needs."),
    ("XDG_CONFIG_HOME", "User presets are read from $XDG_CONFIG_HOME/camtool (default ~/.config/camtool)."),
    ("XDG_CONFIG_DIRS", "System-wide presets are read from camtool/ below each of these directories."),
    ("XDG_DATA_HOME", "The lensfun import is written to $XDG_DATA_HOME/camtool (default ~/.local/share/camtool)."),
]
EXIT_STATUS = [
    ("0", "Success."),
    ("1", "A runtime failure, such as an unreadable or invalid preset or batch file, or output that cannot be "
          "written; or --on-error skip skipped a row. A closed pipe (| head -1) is a normal end, 0."),
    ("2", "Bad usage, or a value outside the physical domain; the message names the option, the value and "
          "the valid range."),
]
UNITS = (
    "Lengths take a unit: 50, 50mm, 3.5cm, 3m, 10ft, 6in, 5'6\", inf. A bare number is millimetres for focal "
    "lengths, CoC and sensor sizes, and metres for subject distances. f-numbers are written 8, f/8 or f8; "
    "times 1/250, 0.5, 2s, 1m30s. Distances are measured from the sensor plane unless --distance-from lens "
    "is given. Options given several values (-N 2.8,4,5.6, or repeated) give one row per combination."
)


def escape(text: str) -> str:
    """Escape text for roff: backslashes, hyphens, non-ASCII characters, and a leading dot or quote."""
    text = text.replace("\\", "\\e").replace("-", "\\-")
    text = "".join(c if ord(c) < 128 else f"\\[u{ord(c):04X}]" for c in text)
    return "\n".join(("\\&" + line) if line[:1] in (".", "'") else line for line in text.split("\n"))


def _split_help(help_text: str) -> tuple[str, str, list[str]]:
    """(summary, description, example lines) from a command docstring.

    The description's paragraphs are dedented and each joined into one line
    (roff fills them); paragraphs are separated by a blank line.
    """
    import inspect

    text = inspect.cleandoc(help_text.replace("\b\n", "").replace("\b", ""))
    summary, _, rest = text.strip().partition("\n")
    description, _, examples = rest.partition("Examples:")
    block, _, after = examples.strip("\n").partition("\n\n")  # the examples end at the first blank line
    description = description.strip() + ("\n\n" + after.strip() if after.strip() else "")
    paragraphs = [" ".join(p.split()) for p in description.strip().split("\n\n") if p.strip()]
    lines = [line.strip() for line in block.splitlines() if line.strip()]
    return summary.strip(), "\n\n".join(paragraphs), lines


KEY_UNITS = {
    "_mm": "millimetres", "_deg": "degrees", "_s": "seconds", "_pct": "percent", "_nm": "nanometres",
}
PLAIN_KEYS = {
    "f_number": "f-number", "working_f_number": "f-number", "needed_f_number": "f-number",
    "f_number_nominal": "f-number (the nominal value printed on the lens)", "magnification": "ratio (1 = 1:1)",
    "crop_factor": "ratio to 36 × 24 mm", "error_estimate": "relative error (0.01 = 1 %)",
    "model": "text: the model that computed the row", "distance_from": "text: sensor or lens",
    "iso": "ISO speed", "ev": "exposure value at the ISO given", "ev100": "exposure value at ISO 100",
    "solved": "text: the setting that was solved for", "kind": "text", "id": "text", "name": "text",
    "summary": "text", "tier": "text", "origin": "text: the file",
}


def key_unit(key: str) -> str:
    """The unit of an output key, from its suffix (``near_mm``: millimetres) or the table of plain keys."""
    if key in PLAIN_KEYS:
        return PLAIN_KEYS[key]
    for suffix, unit in KEY_UNITS.items():
        if key.endswith(suffix):
            return unit
    return "number"


def output_keys(command: click.Command) -> list[str]:
    """Every key the command can output: its declared keys in order, else the KEYS lists of its module."""
    import sys

    module = sys.modules.get(getattr(command.callback, "__module__", "") or "")
    keys: list[str] = list(dict.fromkeys(getattr(command, "output_key_list", ())))
    for name in () if keys else ("KEYS", "DISTANCE_KEYS", "FORWARD_KEYS", "INVERSE_KEYS", "FIXED_KEYS", "EQUIVALENT_KEYS",
                 "LIST_KEYS", "COMPARE_KEYS", "MODEL_KEYS"):
        for key in getattr(module, name, None) or ():
            if key not in keys:
                keys.append(key)
    for key in sorted(getattr(command, "output_keys", ()) or ()):
        if key not in keys:
            keys.append(key)
    return keys


def _option_lines(command: click.Command, ctx: click.Context) -> list[str]:
    out: list[str] = []
    for param in command.get_params(ctx):
        record = param.get_help_record(ctx)
        if record is None:
            continue
        names, help_text = record
        out += [".TP", f"\\fB{escape(names)}\\fR", escape(help_text)]
    return out


def _paragraphs(text: str) -> list[str]:
    out: list[str] = []
    for paragraph in text.split("\n\n"):
        out += ([".PP"] if out else []) + [escape(paragraph)]
    return out


def _arguments(command: click.Command) -> str:
    if isinstance(command, click.Group):
        return "\\fICOMMAND\\fR [\\fIARGS\\fR]..."
    args = [p for p in command.params if isinstance(p, click.Argument)]
    return " ".join(f"\\fI{escape(p.human_readable_name)}\\fR" + ("..." if p.nargs == -1 else "") for p in args)


def render(command: click.Command, name: str, parent: click.Context | None = None) -> str:
    """The roff source of the man page for ``command`` invoked as ``name`` (e.g. ``camtool dof``)."""
    ctx = click.Context(command, info_name=name.split()[-1], parent=parent, help_option_names=HELP_OPTIONS)
    summary, description, examples = _split_help(command.help or "")
    page = name.replace(" ", "-")
    lines = [
        f'.TH {page.upper()} 1 "{MAN_DATE}" "camtool {__version__}" "camtool manual"',
        ".SH NAME", f"{escape(page)} \\- {escape(summary)}",
        ".SH SYNOPSIS", f"\\fB{escape(name)}\\fR [\\fIOPTIONS\\fR] {_arguments(command)}".rstrip(),
        ".SH DESCRIPTION", *_paragraphs(description or summary),
        ".SH UNITS", escape(UNITS),
    ]
    if isinstance(command, click.Group):
        lines += [".SH COMMANDS"]
        for sub in command.list_commands(ctx):
            subcommand = command.get_command(ctx, sub)
            if subcommand is None:
                continue
            lines += [".TP", f"\\fB{escape(name)} {escape(sub)}\\fR",
                      escape(subcommand.get_short_help_str(limit=200))]
            if name != "camtool":
                sub_ctx = click.Context(subcommand, info_name=sub, parent=ctx, help_option_names=HELP_OPTIONS)
                sub_options = _option_lines(subcommand, sub_ctx)
                if sub_options:
                    lines += [".RS", ".PP", "Options:", *sub_options, ".RE"]
    options = _option_lines(command, ctx)
    if options:
        lines += [".SH OPTIONS", *options]
    keys = output_keys(command)
    if keys:
        lines += [".SH OUTPUT KEYS", "The keys of each row in JSON and CSV output (and for \\-\\-field), with their "
                  "units; an infinite value is null in JSON, an empty cell in CSV and inf with \\-\\-field."]
        for key in keys:
            lines += [".TP", f"\\fB{escape(key)}\\fR", escape(key_unit(key))]
    if examples:
        lines += [".SH EXAMPLES", ".nf", *(escape(e) for e in examples), ".fi"]
    lines += [".SH ENVIRONMENT"]
    for var, text in ENVIRONMENT:
        lines += [".TP", f"\\fB{var}\\fR", escape(text)]
    lines += [".SH EXIT STATUS"]
    for code, text in EXIT_STATUS:
        lines += [".TP", f"\\fB{code}\\fR", escape(text)]
    see_also = ["camtool(1)"] if name != "camtool" else []
    if name == "camtool" and isinstance(command, click.Group):
        see_also = [f"camtool\\-{sub}(1)" for sub in command.list_commands(ctx)]
    if see_also:
        lines += [".SH SEE ALSO", ", ".join(f"\\fB{s.split('(')[0]}\\fR({s.split('(')[1]}" for s in see_also)]
    return "\n".join(lines) + "\n"


def pages(group: click.Group, name: str = "camtool") -> dict[str, str]:
    """File name -> roff source for the group's page (``camtool.1``) and every subcommand's page."""
    top = click.Context(group, info_name=name, help_option_names=HELP_OPTIONS)
    result = {f"{name}.1": render(group, name)}
    for sub in group.list_commands(top):
        command = group.get_command(top, sub)
        if command is not None:
            result[f"{name}-{sub}.1"] = render(command, f"{name} {sub}", parent=top)
    return result


def write(group: click.Group, directory: Path) -> list[Path]:
    """Write every page of ``group`` into ``directory`` (created if missing) and return the paths."""
    directory.mkdir(parents=True, exist_ok=True)
    written = []
    for filename, text in pages(group).items():
        path = directory / filename
        path.write_text(text, encoding="utf-8")
        written.append(path)
    return written
