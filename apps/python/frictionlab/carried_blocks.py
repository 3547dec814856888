"""Carrying a generated block over a change that moves no output (python3 -m frictionlab.carried_blocks).

A block's fingerprint covers the physics sources it depends on (frictionlab.doc_blocks), so a
refactor that changes no number (the dimension-generic core, a renamed member) stales the blocks,
and regenerating some takes an hour of runs. A block may instead be carried to the new tree in one
of two ways.

When nothing it depends on changed since the commit its stamp records (the change was elsewhere,
or in what the fingerprint rule counts), no run is needed:

    python3 -m frictionlab.carried_blocks NAME --same-sources DOC [DOC ...]

It checks that the block was current at that commit by that commit's own rule, and that this
tree's rule gives that commit's tree and this one the same fingerprint; the stamp then says
checked=sources.

Otherwise, when runs made with the new tree wrote what the same runs of the block's own sweep
wrote, file for file:

    python3 -m frictionlab.carried_blocks NAME --old OLD_SWEEP --new NEW_SWEEP DOC [DOC ...]

OLD_SWEEP is the sweep the block was made from, NEW_SWEEP the same sweep (some or all of its cases:
the same scene, overrides and seeds) run again with this tree. Every case of NEW_SWEEP must be in
OLD_SWEEP and have written the same outputs: its tables, events and summaries byte for byte, its
HDF5 files' datasets and attributes value for value (HDF5 keeps times of its own in the file), its
run record's scene hash and counts; only the times a run took may differ.

A parameter added to a plugin is recorded, at its default, in every scene it resolves, and changes
the scene's hash. A case whose resolved scene (its run.yaml) is the first run's with keys added, and
nothing else changed, may therefore have a new hash: its outputs must then be the first run's with
the old hash read as the new one, byte for byte as above. That the new keys' defaults keep the old
behaviour is what the outputs show; a changed value, or a key removed, is a different scene. The block's text stays;
its stamp gets this tree's fingerprint and commit, keeps the scenes and seeds it was made from, and
says what it was carried on: carried_from=<commit it was made at> checked=<cases compared>/<runs>.
A reader sees that the numbers were made at the first commit and checked, not remade, at the
second; the regenerating command remains the way to remake them."""
import argparse
import filecmp
import os
import re
import subprocess
import sys
import tempfile
from typing import Iterable, List, Optional

import yaml

from frictionlab import doc_blocks

# What a run's records may differ in between two runs of the same case: the time it took.
TIMES = ("wall_seconds", "cpu_seconds")
# Files that are not outputs of the physics: logs and the figures drawn from the tables.
NOT_OUTPUTS = (".log", ".png", ".svg", ".pdf")


def _load(path: str) -> dict:
    with open(path) as f:
        return yaml.safe_load(f) or {}


def _with_keys_of(new, old):
    """`new` with only the keys `old` has, in every mapping nested alike: a scene as the first run's
    code resolved it, when the new code added parameters."""
    if isinstance(new, dict) and isinstance(old, dict):
        return {k: _with_keys_of(v, old[k]) for k, v in new.items() if k in old}
    if isinstance(new, list) and isinstance(old, list) and len(new) == len(old):
        return [_with_keys_of(n, o) for n, o in zip(new, old)]
    return new


def renamed_scene(old_case: str, new_case: str):
    """(old hash, new hash) when the case's scene, run again, is the first run's with keys added and
    nothing else changed (its hash then changed); None when the hash is the same or the scene differs
    otherwise."""
    old_run, new_run = os.path.join(old_case, "run.yaml"), os.path.join(new_case, "run.yaml")
    if not (os.path.exists(old_run) and os.path.exists(new_run)):
        return None
    old, new = _load(old_run), _load(new_run)
    old_hash, new_hash = str(old.get("scene_hash", "")), str(new.get("scene_hash", ""))
    if not old_hash or old_hash == new_hash or "scene" not in old or "scene" not in new:
        return None
    scene = lambda record: {k: v for k, v in record.items() if k != "output"}
    as_before = _with_keys_of(scene(new["scene"]), scene(old["scene"]))
    if as_before != scene(old["scene"]) or as_before == scene(new["scene"]):
        return None  # a value changed or a key went; or nothing was added, and the hash has no reason to change
    return old_hash, new_hash


def _records_agree(a: str, b: str, renamed=None) -> bool:
    """Two run records (run.yaml, case.yaml) alike but for the times the runs took, the paths
    they were given (the output directory, the command line, the plugins' files) and the threads
    they shared their loops among (the results are the same at any count); with `renamed`,
    the scene's hash is the new one and the scene the first run's with keys added."""
    def essentials(path):
        record = _load(path)
        if renamed and path == b:
            record["scene_hash"] = renamed[0]
            if "scene" in record:
                record["scene"] = _with_keys_of(record["scene"], _load(a).get("scene", {}))
        drop = set(TIMES) | {"command_line", "plugins", "output", "quiet_fraction_of_wall_time",
                             "creep_fraction_of_wall_time", "quiet_seconds_wall", "dynamic_seconds_wall",
                             "creep_seconds_wall", "plugin_files", "scene_path", "threads"}
        def strip(x):
            if isinstance(x, dict):
                return {k: strip(v) for k, v in x.items() if k not in drop}
            if isinstance(x, list):
                return [strip(v) for v in x]
            return x
        return strip(record)
    return essentials(a) == essentials(b)


def _hdf5_agree(a: str, b: str, renamed=None) -> bool:
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
            old_attrs = {k: _renaming(str(v), renamed) for k, v in oa.attrs.items()}
            if old_attrs != {k: str(v) for k, v in ob.attrs.items()}:
                return False
            if isinstance(oa, h5py.Dataset):
                va, vb = oa[()], ob[()]
                if oa.dtype != ob.dtype or np.shape(va) != np.shape(vb):
                    return False
                if not (np.array_equal(va, vb, equal_nan=True) if oa.dtype.kind == "f" else np.array_equal(va, vb)):
                    return False
    return True


def _vtu_agree(a: str, b: str, renamed) -> bool:
    """Two VTU files alike, read by VTK: points, cells and every array value for value, the old
    scene hash read as the new one (the files compress their arrays, so bytes cannot be compared)."""
    import numpy as np
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader

    def read(path):
        reader = vtkXMLUnstructuredGridReader()
        reader.SetFileName(path)
        reader.Update()
        return reader.GetOutput()

    def values(array, rename):
        if array.IsA("vtkStringArray"):
            return [_renaming(array.GetValue(i), rename) for i in range(array.GetNumberOfValues())]
        return vtk_to_numpy(array)

    def same(u, v):
        if isinstance(u, list) or isinstance(v, list):
            return u == v
        return u.dtype == v.dtype and u.shape == v.shape and np.array_equal(u, v, equal_nan=u.dtype.kind == "f")

    ga, gb = read(a), read(b)
    if (ga.GetNumberOfPoints(), ga.GetNumberOfCells()) != (gb.GetNumberOfPoints(), gb.GetNumberOfCells()):
        return False
    if ga.GetNumberOfPoints() and not same(values(ga.GetPoints().GetData(), None), values(gb.GetPoints().GetData(), None)):
        return False
    if ga.GetNumberOfCells() and not (same(values(ga.GetCells().GetConnectivityArray(), None),
                                           values(gb.GetCells().GetConnectivityArray(), None))
                                      and same(vtk_to_numpy(ga.GetCellTypesArray()), vtk_to_numpy(gb.GetCellTypesArray()))):
        return False
    for part in ("GetPointData", "GetCellData", "GetFieldData"):
        da, db = getattr(ga, part)(), getattr(gb, part)()
        names = lambda d: [d.GetAbstractArray(i).GetName() for i in range(d.GetNumberOfArrays())]
        if names(da) != names(db):
            return False
        for i in range(da.GetNumberOfArrays()):
            if not same(values(da.GetAbstractArray(i), renamed), values(db.GetAbstractArray(i), None)):
                return False
    return True


def _renaming(text: str, renamed) -> str:
    return text.replace(renamed[0], renamed[1]) if renamed else text


def _same_text(old: str, new: str, renamed) -> bool:
    if not renamed:
        return filecmp.cmp(old, new, shallow=False)
    with open(old, "rb") as a, open(new, "rb") as b:
        return a.read().replace(renamed[0].encode(), renamed[1].encode()) == b.read()


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
    renamed = renamed_scene(old_case, new_case)
    for rel in new_outputs:
        name = os.path.basename(rel)
        new = os.path.join(new_case, rel)
        old = os.path.join(old_case, rel)
        if not os.path.exists(old):
            found.append(f"{rel} (not in the first run)")
        elif name in ("run.yaml", "case.yaml"):
            if not _records_agree(old, new, renamed):
                found.append(rel)
        elif name.endswith(".h5"):
            if not _hdf5_agree(old, new, renamed):
                found.append(rel)
        elif name.endswith(".vtu") and renamed:
            if not _vtu_agree(old, new, renamed):
                found.append(rel)
        elif not _same_text(old, new, renamed):
            found.append(rel)
    return found


def _runs_made_from(name: str, documents: Iterable[str]) -> Optional[int]:
    """The number of runs block `name` was made from, as its stamp's `scenes=N:HASH` says; None if
    its stamp does not say."""
    for document in documents:
        with open(document) as f:
            opening = re.search(doc_blocks.OPENING.format(name=re.escape(name)), f.read())
        if opening:
            scenes = _stamp_fields(opening["stamp"]).get("scenes", "")
            return int(scenes.split(":")[0]) if ":" in scenes else None
    return None


def carry(name: str, documents: Iterable[str], old_sweep: str, new_sweep: str, runs: Optional[int] = None) -> str:
    """Restamps block `name` in `documents` for this tree (see the module's docstring); returns the
    new stamp, or raises ValueError naming each case and output that differs, changing nothing.
    `runs`: how many runs the block was made from, for its stamp's checked=K/N; by default its stamp's
    `scenes=N:`, else the cases of `old_sweep` (which then holds every run the block was made from)."""
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
    runs = runs or _runs_made_from(name, documents) or len(os.listdir(os.path.join(old_sweep, "cases")))
    return _restamp(name, documents, f"{len(cases)}/{runs}")


def _stamp_fields(stamp: str) -> dict:
    return dict(field.split("=", 1) for field in stamp.split())


def _restamp(name: str, documents: Iterable[str], checked: str) -> str:
    """Gives block `name` in `documents` this tree's fingerprint and commit, keeping the scenes and
    seeds it was made from and saying what carried it; returns the first new stamp."""
    stamps = []
    for document in documents:
        with open(document) as f:
            text = f.read()
        opening = re.search(doc_blocks.OPENING.format(name=re.escape(name)), text)
        if not opening:
            continue
        old = _stamp_fields(opening["stamp"])
        kept = " ".join(f"{k}={old[k]}" for k in ("scene", "scenes", "seeds") if k in old)
        made_at = old.get("carried_from", old.get("commit", "unknown"))
        root = doc_blocks.repository_root(document)
        stamp = (f"fingerprint={doc_blocks.fingerprint(root, name)} commit={doc_blocks.commit(root, name)} "
                 f"{kept} carried_from={made_at} checked={checked}").replace("  ", " ")
        with open(document, "w") as f:
            f.write(text[:opening.start()] + f"<!-- {name} {stamp} -->" + text[opening.end():])
        stamps.append(stamp)
    if not stamps:
        raise ValueError(f"no <!-- {name} --> block in {', '.join(documents)}")
    return stamps[0]


def _tree_at(root: str, commit: str, into: str) -> None:
    archive = subprocess.run(["git", "-C", root, "archive", commit], capture_output=True)
    if archive.returncode != 0:
        raise ValueError(f"commit {commit} is not in this repository: {archive.stderr.decode().strip()}")
    subprocess.run(["tar", "-x", "-C", into], input=archive.stdout, check=True)


def carry_same_sources(name: str, documents: Iterable[str]) -> str:
    """Restamps block `name` when nothing it depends on changed since the commit its stamp records:
    that commit's own fingerprint rule, or this one, gives the stamp's fingerprint on that commit's
    tree (the block was current there), and this tree's rule gives the same fingerprint on that tree and on this one
    (its sources, comments and spacing aside, are the same). No run is needed: the runs would run the
    same code on the same scenes. Raises ValueError naming the files that differ, changing nothing."""
    import importlib.util
    documents = list(documents)
    stamps = [_stamp_fields(m["stamp"]) for d in documents for m in
              [re.search(doc_blocks.OPENING.format(name=re.escape(name)), open(d).read())] if m]
    if not stamps:
        raise ValueError(f"no <!-- {name} --> block in {', '.join(documents)}")
    root = doc_blocks.repository_root(documents[0])
    commit, recorded = stamps[0].get("commit", ""), stamps[0].get("fingerprint", "")
    if not commit or commit == "unknown" or commit.endswith("+changes"):
        raise ValueError(f"<!-- {name} --> was stamped at {commit or 'no commit'}: no committed tree to compare with")
    with tempfile.TemporaryDirectory() as then:
        _tree_at(root, commit, then)
        spec = importlib.util.spec_from_file_location("doc_blocks_then",
                                                      os.path.join(then, "apps/python/frictionlab/doc_blocks.py"))
        rule_then = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(rule_then)
        # Current there by the rule of that commit, or by this one (a stamp made while the rule changed).
        rules = ([rule_then.fingerprint] if name in rule_then.BLOCKS else []) + [doc_blocks.fingerprint]
        if all(rule(then, name) != recorded for rule in rules):
            raise ValueError(f"<!-- {name} --> was not current at {commit} (fingerprint {recorded}): regenerate it")
        if doc_blocks.fingerprint(then, name) != doc_blocks.fingerprint(root, name):
            files_then, files_now = doc_blocks.dependencies(then, name), doc_blocks.dependencies(root, name)
            changed = sorted(set(files_then) ^ set(files_now)) + [
                rel for rel in sorted(set(files_then) & set(files_now))
                if doc_blocks.without_comments(rel, doc_blocks._read(then, rel))
                != doc_blocks.without_comments(rel, doc_blocks._read(root, rel))]
            raise ValueError(f"what <!-- {name} --> depends on changed since {commit}, the block must be carried "
                             f"with runs or regenerated:\n  " + "\n  ".join(changed))
    return _restamp(name, documents, "sources")


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python3 -m frictionlab.carried_blocks", description=__doc__.split("\n")[0])
    parser.add_argument("name", help="the block (frictionlab.doc_blocks.BLOCKS)")
    parser.add_argument("documents", nargs="+", help="the files that hold it")
    parser.add_argument("--old", help="the sweep the block was made from")
    parser.add_argument("--new", help="the same sweep's cases run again with this tree")
    parser.add_argument("--runs", type=int, help="how many runs the block was made from, when its stamp does not "
                        "say (scenes=N:...) and --old holds only some of them")
    parser.add_argument("--same-sources", action="store_true",
                        help="carry without runs when nothing the block depends on changed since its stamp's commit")
    args = parser.parse_args(argv)
    if args.same_sources == bool(args.old or args.new) or (not args.same_sources and not (args.old and args.new)):
        parser.error("give either --old and --new, or --same-sources")
    try:
        print(carry_same_sources(args.name, args.documents) if args.same_sources else
              carry(args.name, args.documents, args.old, args.new, args.runs))
    except ValueError as e:
        print(f"error: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
