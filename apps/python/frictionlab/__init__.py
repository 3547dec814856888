"""FrictionLab from Python: load and validate scenes, run them in-process, read their outputs.

    import frictionlab
    scene = frictionlab.Scene.load("configs/headline.yaml", set=["stages[1].duration=0.01"])
    run = scene.run(output="out/py", progress=True)       # a Run; Ctrl-C stops it cleanly
    v = run.table("interface_velocity")                    # Table: .columns, .values, ["block_3"]
    df = run.frame("precursors")                           # pandas DataFrame
    frictionlab.types(); frictionlab.doc("friction_law", "three_state_junctions")

From a build tree: PYTHONPATH=build/python /usr/bin/python3. Plugins are found as the command line
finds them: `plugin_paths` arguments, the scene's `plugin_paths:`, FRICTIONLAB_PLUGIN_PATH, then the
plugins shipped with this module.
"""
import importlib
import json
import os
from typing import List, Optional, Sequence

from ._errors import Diagnostic, SceneError
from ._run import InterfaceMap, Run, Table, open_run, read_table

__all__ = ["Scene", "Run", "Table", "InterfaceMap", "SceneError", "Diagnostic", "InputError", "RunError", "open_run", "read_table",
           "types", "doc", "version"]
_FROM_CORE = ("_core", "InputError", "RunError", "__version__")


def _load_core():
    """The compiled module, imported on first use: `python3 -m frictionlab.plot` (which `frictionlab
    plot` runs) then needs neither this python3's version of it nor a build of it at all."""
    return importlib.import_module("._core", __name__)  # not `from . import`: that asks __getattr__ first


def __getattr__(name: str):
    if name not in _FROM_CORE:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    core = _load_core()
    return core if name == "_core" else core.version() if name == "__version__" else getattr(core, name)


def __dir__() -> List[str]:
    return sorted(set(globals()) | set(_FROM_CORE))


def version() -> str:
    """The framework version, e.g. "0.1.0"."""
    return _load_core().version()


def _paths(plugin_paths: Sequence[str]) -> List[str]:
    return [os.fspath(p) for p in plugin_paths]


class Scene:
    """A validated scene (share/docs/scene-format.md), with the plugins its types come from.

    Scene.load(path, set=[...]) and Scene.from_yaml(text) apply the same checks as `frictionlab
    check`; a scene with errors raises SceneError, whose `diagnostics` hold every error with its file,
    line and column. scene.run(...) runs it in this process and returns the Run.
    """

    def __init__(self, core):  # a _core._Scene
        self._core = core

    @classmethod
    def load(cls, path, set: Sequence[str] = (), plugin_paths: Sequence[str] = ()) -> "Scene":
        """Reads and validates the scene file `path`; `set` holds `key.path=value` overrides (as
        `--set`), `plugin_paths` extra plugin directories (as `--plugin-path`)."""
        return cls(_load_core()._Scene.load(os.fspath(path), list(set), _paths(plugin_paths)))

    @classmethod
    def from_yaml(cls, text: str, name: str = "<string>", set: Sequence[str] = (),
                  plugin_paths: Sequence[str] = ()) -> "Scene":
        """Validates a scene given as YAML text; `name` stands for the file in messages. Relative
        `plugin_paths:` of the scene are taken from the working directory."""
        return cls(_load_core()._Scene.from_yaml(text, name, list(set), _paths(plugin_paths)))

    @property
    def file(self) -> str:
        """The scene file (or the name given to from_yaml)."""
        return str(self._core.file)

    @property
    def hash(self) -> str:
        """Hash of the resolved scene (every default written out), as run.yaml records it."""
        return self._core.hash

    @property
    def title(self) -> str:
        return self._core.title

    @property
    def seed(self) -> int:
        return self._core.seed

    @property
    def output(self) -> str:
        """The output directory the scene names (`output:`)."""
        return str(self._core.output)

    @property
    def resolved_yaml(self) -> str:
        """The scene with every default written out, as YAML (what run.yaml records)."""
        return self._core.resolved_yaml

    def run(self, output: Optional[str] = None, progress: bool = False, overwrite: bool = False,
            allow_unstable_step: bool = False, resume: bool = False, log_level: str = "warn",
            threads: int = 0) -> Run:
        """Runs the scene in this process and returns its Run.

        output               output directory; as `frictionlab run -o` (an override of `output:`, so
                             the outputs equal the command line's byte for byte)
        progress             one live progress line on stderr
        overwrite            replace an output directory FrictionLab created (`--overwrite`)
        allow_unstable_step  run a time step above the estimated stable one
        resume               go on from the last checkpoint of the stopped run in the output directory
                             (`frictionlab run --resume`; share/docs/checkpoints.md)
        log_level            trace, debug, info, warn, error or off (log lines go to stderr)
        threads              threads the run shares its lattice loops among (`--threads`); 0: all this
                             machine offers; the results are the same at any count

        The GIL is released while stepping. Ctrl-C (SIGINT) stops the run between two steps: its
        tables are closed, run.yaml records status "interrupted" with the step and time reached, and
        KeyboardInterrupt is raised; a checkpoint is written, so run(..., resume=True) goes on from
        there. A run that fails raises RunError; bad input InputError.
        """
        summary = self._core.run(None if output is None else os.fspath(output), progress, overwrite,
                                 allow_unstable_step, resume, log_level, threads)
        return open_run(str(summary["output"]))

    def __repr__(self) -> str:
        return f"Scene({self.file!r}, hash={self.hash!r})"


def types(plugin_paths: Sequence[str] = ()) -> List[dict]:
    """Every kind and type, as `frictionlab list` prints them: dicts with kind, type, library, summary."""
    return _load_core().types(_paths(plugin_paths))


def doc(kind: str, type: Optional[str] = None, plugin_paths: Sequence[str] = ()):
    """The documentation `frictionlab doc KIND/TYPE --format json` prints, as data: for one type a
    dict (kind, type, summary, library, params: key, doc, unit, default, bounds, ...); for a kind
    alone the list of its types."""
    data = json.loads(_load_core().doc_json(kind, type or "", _paths(plugin_paths)))
    return data[0] if type and isinstance(data, list) and len(data) == 1 else data
