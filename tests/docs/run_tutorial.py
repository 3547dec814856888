"""Runs share/docs/tutorial.md as a reader would: its fenced ```sh (or ```bash, ```console) and
```python blocks, in order, in one shell session in a fresh directory that holds the source tree's
configs/, with the build's frictionlab first on PATH and its Python module on PYTHONPATH. Fails
(exit status 1) on the first block that fails, naming its line in the tutorial. Then checks that the
tutorial names what its blocks wrote: every table of every sweep (`sweep.csv`, ...) and every
format of every figure (PNG, SVG).

Usage: run_tutorial.py TUTORIAL.md   (environment: FRICTIONLAB_CLI, FRICTIONLAB_SOURCE_DIR, PYTHONPATH)
"""
import os
import subprocess
import sys
import tempfile
from pathlib import Path

SHELL = ("sh", "bash", "console")


def blocks(markdown):
    """(language, first line number, text) of every fenced block, in order."""
    out, language, start, text = [], None, 0, []
    for n, line in enumerate(Path(markdown).read_text().splitlines(), start=1):
        if line.startswith("```"):
            if language is None:
                language, start, text = line[3:].strip() or "text", n, []
            else:
                out.append((language, start, "\n".join(text) + "\n"))
                language = None
        elif language is not None:
            text.append(line)
    if language is not None:
        sys.exit(f"{markdown}:{start}: unclosed fence")
    return out


def shell_text(language, text):
    if language != "console":
        return text
    # A console block: the lines after "$ " are commands, the others their output.
    return "".join(line[2:] + "\n" for line in text.splitlines() if line.startswith("$ "))


def script(markdown):
    """One bash script running every block, each announced by its line."""
    parts = ["set -euo pipefail\n"]
    ran = 0
    for language, line, text in blocks(markdown):
        if language in SHELL:
            body = shell_text(language, text)
        elif language == "python":
            body = f'"$FRICTIONLAB_TUTORIAL_PYTHON" - <<\'FRICTIONLAB_TUTORIAL_PY\'\n{text}FRICTIONLAB_TUTORIAL_PY\n'
        else:
            continue
        ran += 1
        parts.append(f"echo '--- {Path(markdown).name}:{line} ({language})' >&2\n{body}")
    return "".join(parts), ran


def unnamed_outputs(markdown, work):
    """What the tutorial's runs wrote that its text does not name: a sweep's tables (each as
    `NAME.csv`) and the formats of the figures in any plots/ folder (as PNG, SVG)."""
    text = Path(markdown).read_text()
    missing = []
    for sweep in sorted(Path(work).glob("out/*/sweep.csv")):
        for table in sorted(sweep.parent.glob("*.csv")):
            if f"`{table.name}`" not in text:
                missing.append(f"{table.parent.name}/{table.name}: a sweep table the tutorial does not name")
    plots = sorted(Path(work).glob("out/*/plots"))
    for folder in plots:
        for ext in sorted({p.suffix[1:].upper() for p in folder.iterdir()}):
            if ext not in text:
                missing.append(f"{folder.parent.name}/plots: figures as {ext}, a format the tutorial does not name")
    if not plots:
        missing.append("no plots/ folder: the tutorial draws no figure")
    return missing


def main():
    markdown = Path(sys.argv[1]).resolve()
    source = Path(os.environ["FRICTIONLAB_SOURCE_DIR"])
    cli = Path(os.environ["FRICTIONLAB_CLI"])
    text, ran = script(markdown)
    if ran < 5:
        sys.exit(f"{markdown}: only {ran} command blocks found")
    env = dict(os.environ)
    env["PATH"] = f"{cli.parent}{os.pathsep}{env.get('PATH', '')}"
    env["FRICTIONLAB_TUTORIAL_PYTHON"] = sys.executable
    env.setdefault("MPLBACKEND", "Agg")
    with tempfile.TemporaryDirectory(prefix="frictionlab_tutorial_") as work:
        (Path(work) / "configs").symlink_to(source / "configs")
        (Path(work) / "tutorial.sh").write_text(text)
        result = subprocess.run(["bash", "tutorial.sh"], cwd=work, env=env)
        missing = unnamed_outputs(markdown, work) if result.returncode == 0 else []
    if result.returncode != 0:
        print(f"{markdown.name}: a block failed with status {result.returncode} (the last one announced above)",
              file=sys.stderr)
        return 1
    if missing:
        print("\n".join(f"{markdown.name}: {m}" for m in missing), file=sys.stderr)
        return 1
    print(f"{markdown.name}: {ran} blocks ran")
    return 0


if __name__ == "__main__":
    sys.exit(main())
