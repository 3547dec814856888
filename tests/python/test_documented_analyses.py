"""The package's analyses as the documentation runs them (`python3 -m frictionlab.NAME ARGS` in
README.md and share/docs/): each module is in the built package, and every option the documentation
gives it is one it takes. Their results on campaign tables: test_ensembles.py."""
import glob
import os
import re
import subprocess
import sys

COMMAND = re.compile(r"python3 -m (frictionlab\.\w+)([^`\n]*)")


def documented_commands(source_dir):
    pages = [os.path.join(source_dir, "README.md")] + sorted(glob.glob(os.path.join(source_dir, "share/docs/*.md")))
    for page in pages:
        with open(page) as f:
            for n, line in enumerate(f, 1):
                for m in COMMAND.finditer(line):
                    yield f"{os.path.basename(page)}:{n}", m[1], m[2]


def test_every_documented_analysis_is_a_module_of_the_package_taking_the_documented_options(source_dir):
    commands = [c for c in documented_commands(source_dir) if c[1] != "frictionlab.plot"]
    assert {module for _, module, _ in commands} >= {"frictionlab.li2020_claims", "frictionlab.lattice_convergence"}
    helps = {}
    for where, module, arguments in commands:
        if module not in helps:
            result = subprocess.run([sys.executable, "-m", module, "--help"], capture_output=True, text=True)
            assert result.returncode == 0, f"{where}: {module}: {result.stderr}"
            helps[module] = result.stdout
        for option in re.findall(r"(?<!\S)(--[\w-]+)", arguments):
            assert option in helps[module], f"{where}: {module} takes no {option}"
