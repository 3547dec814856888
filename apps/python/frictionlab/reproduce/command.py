"""`frictionlab reproduce PAPER -o DIR [-j N] [--quick]` (or `python3 -m frictionlab.reproduce`):
runs what a paper shows and writes DIR/report.md, a verdict per statement. Run again with the same
command after an interruption, it goes on where it stopped and gives the same statements."""
import argparse
import os
import shlex
import sys
import time

from . import li2020, report, steps, tromborg2014

PAPERS = {"li2020": li2020, "tromborg2014": tromborg2014}


def configs_folder(given: str) -> str:
    """The shipped scenes: --configs, else configs/ of the working directory (a clone's root), else
    of the source tree this frictionlab was built from (FRICTIONLAB_SOURCE_DIR)."""
    candidates = [given] if given else ["configs", os.path.join(os.environ.get("FRICTIONLAB_SOURCE_DIR", ""),
                                                               "configs")]
    for c in candidates:
        if c and os.path.isfile(os.path.join(c, "headline.yaml")):
            return os.path.abspath(c)
    raise SystemExit(f"cannot find the shipped scenes (configs/headline.yaml) in {' or '.join(candidates)}: "
                     "run from the repository's root or give --configs")


def main(argv=None):
    parser = argparse.ArgumentParser(prog="frictionlab reproduce", description="Runs what a paper shows and writes "
                                     "DIR/report.md, a verdict per statement of the paper.")
    parser.add_argument("paper", help="the paper: " + ", ".join(PAPERS))
    parser.add_argument("-o", "--output", help="output directory (default: out/reproduce-PAPER)")
    parser.add_argument("-j", "--jobs", type=int, default=os.cpu_count() or 1, help="runs at once")
    parser.add_argument("--quick", action="store_true",
                        help="fewer seeds at ten times the drive: the report's structure in minutes")
    parser.add_argument("--configs", default="", help="folder of the shipped scenes (default: ./configs)")
    parser.add_argument("--check", action="store_true",
                        help="only validate every step's sweep and the scene of each of its cases (frictionlab sweep --check)")
    parser.add_argument("--write-docs", action="store_true",
                        help="also replace the documentation's generated blocks of this paper with what it measured")
    args = parser.parse_args(argv)
    if args.paper not in PAPERS:
        parser.exit(2, f"frictionlab reproduce: unknown paper '{args.paper}'; the papers: {', '.join(PAPERS)}\n")
    if args.jobs < 1:
        parser.exit(2, "frictionlab reproduce: --jobs must be at least 1\n")
    if args.write_docs and args.quick:
        parser.exit(2, "frictionlab reproduce: --write-docs publishes the full reproduction's numbers, not --quick's\n")
    paper = PAPERS[args.paper]
    out = args.output or os.path.join("out", f"reproduce-{args.paper}" + ("-quick" if args.quick else ""))
    os.makedirs(out, exist_ok=True)
    configs = configs_folder(args.configs)
    command = "frictionlab reproduce " + " ".join(shlex.quote(a) for a in (argv if argv is not None else sys.argv[1:]))
    start = time.monotonic()

    def log(message):
        print(f"[{time.monotonic() - start:6.0f} s] {message}", flush=True)

    if args.check:
        sys.exit(0 if all(steps.check_step(s, configs, out) for s in paper.steps(args.quick)) else 2)
    outcomes = steps.run_steps(paper.steps(args.quick), configs, out, args.jobs, log)
    log("measuring and writing the report")
    statements, figures, notes = paper.measure(outcomes, out)
    path = report.write(out, paper.TITLE + (" (quick: fewer seeds, ten times the drive)" if args.quick else ""),
                        command, statements, outcomes, figures, notes)
    if args.write_docs:
        for doc in paper.write_docs(outcomes, statements, os.path.dirname(configs)):
            log(f"wrote {doc}")
    failed = sum(len(o.failed) for o in outcomes.values())
    log(f"{path}: {len(statements)} statements" + (f"; {failed} runs failed (listed there)" if failed else ""))
    sys.exit(1 if failed else 0)
