#!/usr/bin/env python3
"""Adds the random robustness run's first-build failures to the saved cases of
tests/extrude/random_cases_test.cpp (tests/data/extrude/random/), then prints the lines that
tests/data/extrude/random/still_failing.txt should hold for the saved cases as they build now.

  CORBEL_RANDOM_NO_RETRY=1 build/tests/corbel_extrude_tests --gtest_filter='RandomRobustness*'  # from build/tests
  scripts/extrude_random_cases.py [FAILURE_DIR] [--cli PATH] [--dest DIR]

FAILURE_DIR (default build/tests/extrude-random-failures) is read with its rebuilt/ subfolder, so
a run with rebuilds works as well. A case already saved is left as it is: a case that ever failed
stays, also once it closes. The files are written with each loop's points on one line (the
numbers as Python prints them: shortest round trip, so the plan is the same to the bit).
The list is printed, not written: compare it with still_failing.txt and edit that by hand
(the test says which line to delete when a listed case closes)."""
import json
import sys
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from extrude_failure_classes import run  # noqa: E402


def compact(value, indent=0):
    pad = " " * indent
    if isinstance(value, dict):
        if not value:
            return "{}"
        items = [f'{pad} {json.dumps(k)}: {compact(v, indent + 1)}' for k, v in value.items()]
        return "{\n" + ",\n".join(items) + "\n" + pad + "}"
    if isinstance(value, list):
        flat = all(not isinstance(v, (dict, list)) or (isinstance(v, list) and all(
            not isinstance(w, (dict, list)) for w in v)) for v in value)
        if flat:
            return json.dumps(value, separators=(",", ":"))
        return "[\n" + ",\n".join(pad + " " + compact(v, indent + 1) for v in value) + "\n" + pad + "]"
    return json.dumps(value)


def main():
    args = sys.argv[1:]
    cli = "build/src/cli/corbel-cli"
    dest = Path("tests/data/extrude/random")
    for flag in ("--cli", "--dest"):
        if flag in args:
            i = args.index(flag)
            if flag == "--cli":
                cli = args[i + 1]
            else:
                dest = Path(args[i + 1])
            del args[i : i + 2]
    folder = Path(args[0] if args else "build/tests/extrude-random-failures")
    dest.mkdir(parents=True, exist_ok=True)
    added = 0
    for case in sorted(folder.glob("*.corbel")) + sorted((folder / "rebuilt").glob("*.corbel")):
        target = dest / case.name
        if target.exists():
            continue
        doc = json.loads(case.read_text())
        text = compact(doc) + "\n"
        assert json.loads(text) == doc
        target.write_text(text)
        added += 1
    cases = sorted(dest.glob("*.corbel"), key=lambda p: (len(p.stem), p.stem))
    print(f"# {added} added, {len(cases)} saved; still failing after rebuilds (NAME  CLASS):", file=sys.stderr)
    with ThreadPoolExecutor(2) as pool:
        results = list(pool.map(lambda c: run(cli, c), cases))
    for case, (cls, factor) in zip(cases, results):
        if cls != "closed now" and factor is None:
            print(f"{case.stem}  {cls}")


if __name__ == "__main__":
    main()
