"""Every C++ source of the project follows .clang-format: lists the files clang-format would
change and exits 1 if there is any. Usage: check_format.py CLANG_FORMAT SOURCE_DIR."""
import pathlib
import subprocess
import sys

FOLDERS = ("core", "plugins", "apps", "tests", "share/plugin_template")
SUFFIXES = {".cpp", ".hpp", ".h"}


def main() -> int:
    clang_format, root = sys.argv[1], pathlib.Path(sys.argv[2])
    files = sorted(p for folder in FOLDERS for p in (root / folder).rglob("*") if p.suffix in SUFFIXES)
    unformatted = []
    for path in files:
        result = subprocess.run([clang_format, "--dry-run", "--Werror", str(path)], capture_output=True, text=True)
        if result.returncode != 0:
            unformatted.append(path.relative_to(root))
    for path in unformatted:
        print(f"{path}: not formatted (run: {clang_format} -i {path})")
    print(f"{len(files) - len(unformatted)} of {len(files)} files follow .clang-format")
    return 1 if unformatted or not files else 0


if __name__ == "__main__":
    sys.exit(main())
