"""Carrying a generated block over a change that moves no output (python3 -m frictionlab.carried_blocks).

A block's fingerprint covers every physics source (frictionlab.doc_blocks), so a refactor that
changes no number (the dimension-generic core, a renamed member) stales every block, and
regenerating some takes an hour of runs. A block may instead be carried to the new tree when runs
made with it wrote what the same runs of the block's own sweep wrote, file for file:

    python3 -m frictionlab.carried_blocks NAME --old OLD_SWEEP --new NEW_SWEEP DOC [DOC ...]

OLD_SWEEP is the sweep the block was made from, NEW_SWEEP the same sweep (some or all of its cases:
the same scene, overrides and seeds) run again with this tree. Every case of NEW_SWEEP must be in
OLD_SWEEP and have written the same outputs: its tables, events and summaries byte for byte, its
HDF5 files' datasets and attributes value for value (HDF5 keeps times of its own in the file), its
run record's scene hash and counts; only the times a run took may differ. The block's text stays;
its stamp gets this tree's fingerprint and commit, keeps the scenes and seeds it was made from, and
says what it was carried on: carried_from=<commit it was made at> checked=<cases compared>/<runs>.
A reader sees that the numbers were made at the first commit and checked, not remade, at the
second; the regenerating command remains the way to remake them."""
import argparse
import filecmp
import os
import re
import sys
from typing import Iterable, List

import yaml

from frictionlab import doc_blocks

# What a run's records may differ in between two runs of the same case: the time it took.
TIMES = ("wall_seconds", "cpu_seconds")
# Files that are not outputs of the physics: logs and the figures drawn from the tables.
NOT_OUTPUTS = (".log", ".png", ".svg", ".pdf")


def _records_agree(a: str, b: str) -> bool:
    """Two run records (run.yaml, case.yaml) alike but for the times the runs took and the paths
    they were given (the output directory, the command line, the plugins' files)."""
    def essentials(path):
        with open(path) as f:
            record = yaml.safe_load(f) or {}
        drop = set(TIMES) | {"command_line", "plugins", "output", "quiet_fraction_of_wall_time",
                             "creep_fraction_of_wall_time", "quiet_seconds_wall", "dynamic_seconds_wall",
                             "creep_seconds_wall", "plugin_files", "scene_path"}
        def strip(x):
            if isinstance(x, dict):
                return {k: strip(v) for k, v in x.items() if k not in drop}
            if isinstance(x, list):
                return [strip(v) for v in x]
            return x
        return strip(record)
    return essentials(a) == essentials(b)


def _hdf5_agree(a: str, b: str) -> bool:
    import h5py
    import numpy as np
    with h5py.File(a) as fa, h5py.File(b) as fb:
        names_a, names_b = [], []
        fa.visit(names_a.append)
        fb.visit(names_b.append)
        if names_a != names_b:
            return False
        for name in [""] + names_a:
            oa, ob = (fa, fb) if name == "" else (fa[name], fb[name])
            if {k: str(v) for k, v in oa.attrs.items()} != {k: str(v) for k, v in ob.attrs.items()}:
                return False
            if isinstance(oa, h5py.Dataset):
                va, vb = oa[()], ob[()]
                if oa.dtype != ob.dtype or np.shape(va) != np.shape(vb):
                    return False
                if not (np.array_equal(va, vb, equal_nan=True) if oa.dtype.kind == "f" else np.array_equal(va, vb)):
                    return False
    return True


def _outputs(case: str) -> List[str]:
    """The outputs of a case's run, as paths below it: not its logs or figures."""
    return sorted(os.path.relpath(os.path.join(folder, name), case)
                  for folder, _, names in os.walk(case) if os.path.basename(folder) != "logs"
                  for name in names if not name.endswith(NOT_OUTPUTS))


def differences(old_case: str, new_case: str) -> List[str]:
    """The outputs of a case run again (`new_case`) that are not what its first run wrote, as
    paths below the case; empty if every output agrees."""
    new_outputs = _outputs(new_case)
    found = [f"{rel} (not written again)" for rel in sorted(set(_outputs(old_case)) - set(new_outputs))]
    for rel in new_outputs:
        name = os.path.basename(rel)
        new = os.path.join(new_case, rel)
        old = os.path.join(old_case, rel)
        if not os.path.exists(old):
            found.append(f"{rel} (not in the first run)")
        elif name in ("run.yaml", "case.yaml"):
            if not _records_agree(old, new):
                found.append(rel)
        elif name.endswith(".h5"):
            if not _hdf5_agree(old, new):
                found.append(rel)
        elif not filecmp.cmp(old, new, shallow=False):
            found.append(rel)
    return found


def carry(name: str, documents: Iterable[str], old_sweep: str, new_sweep: str) -> str:
    """Restamps block `name` in `documents` for this tree (see the module's docstring); returns the
    new stamp, or raises ValueError naming each case and output that differs, changing nothing."""
    cases = sorted(os.listdir(os.path.join(new_sweep, "cases")))
    if not cases:
        raise ValueError(f"{new_sweep}: no case was run again, nothing shows the outputs unchanged")
    problems = []
    for case in cases:
        old_case = os.path.join(old_sweep, "cases", case)
        if not os.path.isdir(old_case):
            problems.append(f"{case}: not a case of {old_sweep}")
            continue
        problems += [f"{case}: {rel}" for rel in differences(old_case, os.path.join(new_sweep, "cases", case))]
    if problems:
        raise ValueError("the outputs differ, the block must be regenerated:\n  " + "\n  ".join(problems))
    runs = len(os.listdir(os.path.join(old_sweep, "cases")))
    stamps = []
    for document in documents:
        with open(document) as f:
            text = f.read()
        opening = re.search(doc_blocks.OPENING.format(name=re.escape(name)), text)
        if not opening:
            continue
        old = dict(field.split("=", 1) for field in opening["stamp"].split())
        kept = " ".join(f"{k}={old[k]}" for k in ("scene", "scenes", "seeds") if k in old)
        made_at = old.get("carried_from", old.get("commit", "unknown"))
        root = doc_blocks.repository_root(document)
        stamp = (f"fingerprint={doc_blocks.fingerprint(root, name)} commit={doc_blocks.commit(root, name)} "
                 f"{kept} carried_from={made_at} checked={len(cases)}/{runs}").replace("  ", " ")
        with open(document, "w") as f:
            f.write(text[:opening.start()] + f"<!-- {name} {stamp} -->" + text[opening.end():])
        stamps.append(stamp)
    if not stamps:
        raise ValueError(f"no <!-- {name} --> block in {', '.join(documents)}")
    return stamps[0]


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python3 -m frictionlab.carried_blocks", description=__doc__.split("\n")[0])
    parser.add_argument("name", help="the block (frictionlab.doc_blocks.BLOCKS)")
    parser.add_argument("documents", nargs="+", help="the files that hold it")
    parser.add_argument("--old", required=True, help="the sweep the block was made from")
    parser.add_argument("--new", required=True, help="the same sweep's cases run again with this tree")
    args = parser.parse_args(argv)
    try:
        print(carry(args.name, args.documents, args.old, args.new))
    except ValueError as e:
        print(f"error: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
