"""Generated blocks of Markdown documents: the text between <!-- NAME ... --> and <!-- /NAME --> is
what a command measured, and the command replaces it (frictionlab.li2020_claims,
frictionlab.lattice_convergence, frictionlab.reproduce, share/scripts/update-readme-figures and
event-matrix-table).

A published number must not go stale in silence: each block's opening marker records what made it,
the commit, the runs' scene hashes and seeds, and a fingerprint of everything its numbers depend on
(BLOCKS: the core's physics sources, the plugins whose types its inputs name, its scenes, its
analysis code). tests/python/test_doc_blocks.py fails
for a block whose fingerprint no longer matches the tree, naming the command that regenerates it.
The fingerprint ignores comments and white space, so that rewording or reformatting a source does
not call for new runs, and any other change does; a change shown to move no output may carry a block
over instead (frictionlab.carried_blocks, its stamp then saying so)."""
import hashlib
import os
import re
import subprocess
from typing import Dict, Iterable, List, NamedTuple, Optional, Sequence

# What every block's numbers depend on: the code that simulates and tabulates. Of the plugins, a
# block depends on those whose types its inputs name (plugin_folders): a plugin no scene of it can
# load does not move its numbers.
PHYSICS = ("core/src", "core/include", "apps/campaign")
PLUGINS = "plugins"
SOURCE_SUFFIXES = (".cpp", ".hpp", ".h", ".py", ".yaml")
# How a plugin's type declares the name a scene gives it.
TYPE_NAME = re.compile(r'static\s+constexpr\s+std::string_view\s+type\s*=\s*"([a-z0-9_]+)"')


class Block(NamedTuple):
    inputs: Sequence[str]  # files and folders below the repository's root, besides PHYSICS
    command: str           # what regenerates it


LI2020_CAMPAIGNS = ("configs/li2020/campaign_scene.yaml", "configs/li2020/fig7_precursor_scaling.yaml",
                    "configs/li2020/fig8_nonuniform_loading.yaml")
LATTICE = ("configs/li2020/campaign_scene.yaml", "apps/python/frictionlab/lattice_convergence.py",
           "apps/python/frictionlab/ensembles.py")

BLOCKS: Dict[str, Block] = {
    "crossing-speeds": Block(("configs/headline.yaml", "share/scripts/update-readme-figures"),
                             "share/scripts/update-readme-figures --headline-only"),
    "li2020-claims": Block(LI2020_CAMPAIGNS + ("apps/python/frictionlab/li2020_claims.py",
                                               "apps/python/frictionlab/ensembles.py"),
                           "python3 -m frictionlab.li2020_claims FIG7 FIG8 --write README.md share/docs/campaigns.md "
                           "(FIG7, FIG8: the sweeps' outputs, or a reproduction's runs/fig7, runs/fig8)"),
    "fig8-means": Block(LI2020_CAMPAIGNS + ("apps/python/frictionlab/li2020_claims.py",),
                        "python3 -m frictionlab.li2020_claims FIG7 FIG8 --write share/docs/campaigns.md"),
    "fig7-means": Block(LI2020_CAMPAIGNS + ("apps/python/frictionlab/li2020_claims.py",),
                        "python3 -m frictionlab.li2020_claims FIG7 FIG8 --write share/docs/campaigns.md"),
    "li2020-reproduction": Block(("configs/headline.yaml", "configs/li2020", "apps/python/frictionlab/reproduce",
                                  "apps/python/frictionlab/li2020_claims.py", "apps/python/frictionlab/ensembles.py"),
                                 "frictionlab reproduce li2020 -o out/li2020 -j 2 --write-docs"),
    "tromborg2014-reproduction": Block(("configs/tromborg2014", "apps/python/frictionlab/reproduce",
                                        "apps/python/frictionlab/ensembles.py"),
                                       "frictionlab reproduce tromborg2014 -o out/tromborg2014 -j 2 --write-docs"),
    "lattice-convergence": Block(LATTICE + ("configs/li2020/lattice_convergence.yaml",),
                                 "python3 -m frictionlab.lattice_convergence (lattice-resolution.md says how)"),
    "lattice-convergence-per-node": Block(LATTICE + ("configs/li2020/lattice_convergence_per_node.yaml",),
                                          "python3 -m frictionlab.lattice_convergence (lattice-resolution.md)"),
    "junction-noise": Block(LATTICE + ("configs/li2020/junction_noise.yaml",),
                            "python3 -m frictionlab.lattice_convergence (lattice-resolution.md)"),
    "event-matrix": Block(("configs/headline.yaml", "configs/peer_laws", "tests/scenes/test_event_conformance.cpp",
                           "share/scripts/event-matrix-table"),
                          "share/scripts/event-matrix-table (theory.md §5a says how)"),
}

OPENING = r"<!-- {name}(?P<stamp>(?: [a-z_]+=[^ ]*)*) -->"


def repository_root(path: str) -> str:
    """The source tree holding `path` (the folder with core/, plugins/ and CMakeLists.txt)."""
    here = os.path.dirname(os.path.abspath(path))
    while here != os.path.dirname(here):
        if all(os.path.exists(os.path.join(here, p)) for p in ("core", "plugins", "CMakeLists.txt")):
            return here
        here = os.path.dirname(here)
    raise ValueError(f"{path} is not inside a FrictionLab source tree")


def files_below(root: str, entries: Iterable[str]) -> List[str]:
    out = set()
    for entry in entries:
        full = os.path.join(root, entry)
        if os.path.isfile(full):
            out.add(entry)
        for folder, _, names in os.walk(full):
            out.update(os.path.relpath(os.path.join(folder, n), root) for n in names if n.endswith(SOURCE_SUFFIXES))
    return sorted(out)


def without_comments(path: str, text: str) -> str:
    """The text without comments and white space: what a change of wording or layout leaves alone."""
    if path.endswith((".cpp", ".hpp", ".h")):
        text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
        text = re.sub(r"//[^\n]*", "", text)
    else:
        text = re.sub(r"(?m)^\s*#[^\n]*", "", text)  # whole-line comments of YAML, Python, shell
        text = re.sub(r"(?m)\s+#\s[^\n]*", "", text)
    return re.sub(r"\s+", "", text)


def _read(root: str, rel: str) -> str:
    with open(os.path.join(root, rel), encoding="utf-8", errors="replace") as f:
        return f.read()


def plugin_folders(root: str, inputs: Iterable[str]) -> List[str]:
    """The plugin folders (plugins/NAME) declaring a type that the files of `inputs` name as a word:
    those a block's scenes, sweeps and tests can load. Naming more than is loaded costs only an
    early regeneration; a plugin that is not named cannot run in the block's runs."""
    words = set()
    for rel in files_below(root, inputs):
        words.update(re.findall(r"[a-z0-9_]+", _read(root, rel)))
    folders = []
    plugins = os.path.join(root, PLUGINS)
    for folder in sorted(os.listdir(plugins)) if os.path.isdir(plugins) else []:
        rel = os.path.join(PLUGINS, folder)
        types = {t for f in files_below(root, (rel,)) if f.endswith((".hpp", ".h")) for t in TYPE_NAME.findall(_read(root, f))}
        if types & words:
            folders.append(rel)
    return folders


def dependencies(root: str, name: str) -> List[str]:
    """Every file the block's numbers depend on: the physics, the plugins its inputs name, its inputs."""
    inputs = tuple(BLOCKS[name].inputs)
    return files_below(root, tuple(PHYSICS) + tuple(plugin_folders(root, inputs)) + inputs)


def fingerprint(root: str, name: str) -> str:
    """12 hex digits of the SHA-256 of the block's dependencies, comments and spacing left out."""
    digest = hashlib.sha256()
    for rel in dependencies(root, name):
        digest.update(rel.encode() + b"\0" + without_comments(rel, _read(root, rel)).encode() + b"\0")
    return digest.hexdigest()[:12]


def commit(root: str, name: str) -> str:
    """The commit the tree is at (short), with +changes when what the block depends on has
    uncommitted changes."""
    def git(*args):
        return subprocess.run(["git", "-C", root, *args], capture_output=True, text=True).stdout.strip()
    head = git("rev-parse", "--short", "HEAD") or "unknown"
    inputs = dependencies(root, name)
    return head + ("+changes" if head != "unknown" and inputs and git("status", "--porcelain", "--", *inputs) else "")


def seed_range(seeds: Iterable) -> str:
    """Runs' seeds as a stamp records them: 1-10, or 3."""
    ordered = sorted(int(x) for x in set(seeds))
    return f"{ordered[0]}-{ordered[-1]}" if len(ordered) > 1 else str(ordered[0]) if ordered else ""


def runs_of(*directories: str):
    """(scene hashes, seeds) of the sweeps in `directories` as their sweep.csv lists them; none for a
    directory without one."""
    import pandas as pd
    tables = [pd.read_csv(os.path.join(d, "sweep.csv")) for d in directories
              if os.path.exists(os.path.join(d, "sweep.csv"))]
    if not tables:
        return [], ""
    runs = pd.concat(tables)
    hashes = runs["scene_hash"].dropna().astype(str).tolist() if "scene_hash" in runs else []
    return hashes, seed_range(runs["seed"].dropna()) if "seed" in runs else ""


def stamp(root: str, name: str, scene_hashes: Iterable[str] = (), seeds: str = "") -> str:
    parts = [f"fingerprint={fingerprint(root, name)}", f"commit={commit(root, name)}"]
    hashes = sorted({h for h in scene_hashes if h})
    if hashes:  # one run's scene hash, or a digest of many (each seed's scene has its own)
        parts.append(f"scene={hashes[0]}" if len(hashes) == 1 else
                     f"scenes={len(hashes)}:{hashlib.sha256(','.join(hashes).encode()).hexdigest()[:12]}")
    if seeds:
        parts.append(f"seeds={seeds}")
    return " ".join(parts)


def replace_block(path: str, name: str, text: str, scene_hashes: Iterable[str] = (), seeds: str = "") -> None:
    """Replaces what stands between the `name` markers of the file at `path` with `text` and stamps
    the opening marker; raises ValueError, leaving the file as it was, unless it has exactly one
    such block. A block on one line (text without a newline) stays on one line."""
    if name not in BLOCKS:
        raise ValueError(f"{name}: not a registered generated block (frictionlab.doc_blocks.BLOCKS)")
    with open(path) as f:
        old = f.read()
    opening = "<!-- " + name + " " + stamp(repository_root(path), name, scene_hashes, seeds) + " -->"
    separator = "\n" if text.endswith("\n") else ""
    new, n = re.subn(OPENING.format(name=re.escape(name)) + r"\n?.*?(<!-- /" + re.escape(name) + " -->)",
                     lambda m: opening + separator + text + m[m.lastindex], old, flags=re.S)
    if n != 1:
        raise ValueError(f"{path}: {n} <!-- {name} --> blocks, not one")
    with open(path, "w") as f:
        f.write(new)


class Found(NamedTuple):
    document: str
    name: str
    recorded: Optional[str]  # the fingerprint its marker records, None if none


def blocks_in(path: str) -> List[Found]:
    with open(path) as f:
        text = f.read()
    found = []
    for m in re.finditer(r"<!-- ([a-z0-9-]+)((?: [a-z_]+=[^ ]*)*) -->", text):
        if f"<!-- /{m[1]} -->" not in text:
            continue
        recorded = re.search(r"fingerprint=([0-9a-f]+)", m[2] or "")
        found.append(Found(path, m[1], recorded[1] if recorded else None))
    return found


def stale(root: str, documents: Iterable[str]) -> List[str]:
    """Each generated block of `documents` that is unregistered, unstamped or made from another tree
    than this one, in words with the command that regenerates it."""
    problems = []
    for doc in documents:
        for b in blocks_in(doc):
            where = f"{os.path.relpath(doc, root)}: <!-- {b.name} -->"
            if b.name not in BLOCKS:
                problems.append(f"{where} is not a registered generated block (frictionlab.doc_blocks.BLOCKS)")
            elif b.recorded != fingerprint(root, b.name):
                problems.append(f"{where} was made from other code or scenes than these "
                                f"(fingerprint {b.recorded}, now {fingerprint(root, b.name)}): regenerate it with "
                                f"{BLOCKS[b.name].command}")
    return problems
