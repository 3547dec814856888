"""The runs of a reproduction, each step a sweep of the `frictionlab` command line into
DIR/runs/STEP: a sweep runs again into its output goes on where it stopped (finished cases are not
run again, a killed one resumes from its checkpoint), so a reproduction interrupted anyhow (Ctrl-C,
kill -9) and started again with the same command finishes the same runs."""
import dataclasses
import os
import shutil
import subprocess
from typing import Dict, List, Optional, Sequence

import pandas as pd
import yaml


@dataclasses.dataclass
class Step:
    """One sweep: `scene` (below the configs folder) over `cases` (name: overrides) and `grid` (key:
    values), each with `seeds` seeds, every run with the overrides `common`; or a shipped sweep file
    (`sweep`, below configs) as it is."""
    name: str
    what: str  # for the report: what the step runs
    scene: str = ""
    seeds: int = 1
    cases: Dict[str, List[str]] = dataclasses.field(default_factory=dict)
    grid: Dict[str, list] = dataclasses.field(default_factory=dict)
    common: List[str] = dataclasses.field(default_factory=list)
    sweep: str = ""

    def sweep_file(self, configs: str, folder: str) -> str:
        """The sweep file to run: the shipped one, or one written into `folder` for this step."""
        if self.sweep:
            return os.path.join(configs, self.sweep)
        cases = self.cases or {"base": []}
        content = {"title": f"reproduction step {self.name}: {self.what}",
                   "scene": os.path.abspath(os.path.join(configs, self.scene)),
                   "cases": [{"name": name, "set": self.common + overrides} for name, overrides in cases.items()],
                   "seeds": self.seeds}
        if self.grid:
            content["grid"] = self.grid
        os.makedirs(folder, exist_ok=True)
        path = os.path.join(folder, f"{self.name}.yaml")
        text = yaml.safe_dump(content, sort_keys=False, width=1000)
        if not os.path.exists(path) or open(path).read() != text:
            with open(path, "w") as f:
                f.write(text)
        return path


@dataclasses.dataclass
class Outcome:
    """What a step left: its sweep's table, the runs that failed, and their processor time."""
    step: Step
    directory: str
    runs: Optional[pd.DataFrame]  # sweep.csv; None if the sweep wrote none
    exit_code: int

    @property
    def failed(self) -> pd.DataFrame:
        if self.runs is None:
            return pd.DataFrame(columns=["run", "status", "reason"])
        return self.runs[self.runs["status"] != "done"]

    @property
    def cpu_seconds(self) -> float:
        return 0.0 if self.runs is None else float(self.runs["cpu_seconds"].fillna(0).sum())

    def run_directories(self, case: Optional[str] = None) -> List[str]:
        """The finished runs' directories (of one case, if given), in order of case and seed."""
        if self.runs is None:
            return []
        done = self.runs[self.runs["status"] == "done"]
        if case is not None:
            done = done[done["case"] == case]
        return [os.path.join(self.directory, "cases", r) for r in done["run"]]


def cli() -> str:
    """The frictionlab command line: the one that started this reproduction (FRICTIONLAB_CLI), else
    the one on PATH."""
    found = os.environ.get("FRICTIONLAB_CLI") or shutil.which("frictionlab")
    if not found:
        raise SystemExit("cannot find the frictionlab command: set FRICTIONLAB_CLI or put it on PATH")
    return found


def check_step(step: Step, configs: str, out: str) -> bool:
    """Validates the step's sweep and every case's scene; errors go to stderr as the sweep says them."""
    return subprocess.run([cli(), "sweep", "--check", "-q", step.sweep_file(configs, os.path.join(out, "sweeps"))],
                          stdout=subprocess.DEVNULL).returncode == 0


def run_step(step: Step, configs: str, out: str, jobs: int, log) -> Outcome:
    """Runs (or goes on with) one step's sweep; a failing run is recorded, not raised."""
    directory = os.path.join(out, "runs", step.name)
    command = [cli(), "sweep", step.sweep_file(configs, os.path.join(out, "sweeps")), "-o", directory,
               "-j", str(jobs), "-q"]
    log(f"{step.name}: {step.what}")
    code = subprocess.run(command).returncode
    table = os.path.join(directory, "sweep.csv")
    runs = pd.read_csv(table, keep_default_na=False, na_values=["nan", ""]) if os.path.exists(table) else None
    return Outcome(step, directory, runs, code)


def run_steps(steps: Sequence[Step], configs: str, out: str, jobs: int, log) -> Dict[str, Outcome]:
    return {s.name: run_step(s, configs, out, jobs, log) for s in steps}
