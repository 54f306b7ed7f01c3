#!/usr/bin/env python3
"""Groups the random robustness run's first-build failures (build/tests/extrude-random-failures/
*.corbel, still failing, and its rebuilt/ subfolder, closed by a rebuild with wider tolerances)
into classes by running `corbel-cli extrude CASE --stats --no-retry` on each and reading its error
and warnings, then says per class how many `corbel-cli extrude CASE --stats` (with rebuilds)
closes. Usage: scripts/extrude_failure_classes.py [FAILURE_DIR] [--cli PATH] [--list CLASS]"""
import json
import subprocess
import sys
from collections import Counter, defaultdict
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path


def classify(error, warnings):
    w = " ".join(warnings)
    if "the roof cannot close" in error:
        return "roof cannot close"
    if "cascade" in error or "cycle" in error:
        return "event cycle"
    if "time limit" in error:
        return "time limit"
    if "diverged" in w:
        return "diverged"
    if "did not close" in w:
        return "capped"
    if "overlapped itself" in w:
        return "overlap-warned"
    if "could not be placed" in w:
        return "face placement"
    if "not closed" in error:
        return "unclosed without warning" if not warnings else "unclosed, other warning"
    if "2-manifold" in error:
        return "non-manifold"
    if "crosses itself" in error:
        return "face crossing itself"
    return "other: " + error[:60]


def stats(cli, path, *extra):
    p = subprocess.run([cli, "extrude", str(path), "--stats", *extra], capture_output=True, text=True)
    for line in p.stdout.splitlines():
        j = json.loads(line)
        if "summary" not in j:
            return j
    return None


def run(cli, path):
    first = stats(cli, path, "--no-retry")
    if first is None or "error" not in first:
        return "closed now", None
    again = stats(cli, path)
    rebuilt = again is not None and "error" not in again
    return classify(first["error"], first.get("warnings", [])), (again.get("tolerance_factor") if rebuilt else None)


def main():
    args = sys.argv[1:]
    cli = "build/src/cli/corbel-cli"
    show = None
    if "--cli" in args:
        i = args.index("--cli")
        cli = args[i + 1]
        del args[i : i + 2]
    if "--list" in args:
        i = args.index("--list")
        show = args[i + 1]
        del args[i : i + 2]
    folder = Path(args[0] if args else "build/tests/extrude-random-failures")
    cases = sorted(folder.glob("*.corbel")) + sorted((folder / "rebuilt").glob("*.corbel"))
    with ThreadPoolExecutor(2) as pool:
        results = list(pool.map(lambda c: run(cli, c), cases))
    counts = Counter(r[0] for r in results)
    closed = Counter(r[0] for r in results if r[1] is not None)
    members = defaultdict(list)
    for c, r in zip(cases, results):
        members[r[0]].append(c.stem + (f" (rebuilt {r[1]:g}x)" if r[1] is not None else ""))
    print(" first  rebuilt  class")
    for k, n in counts.most_common():
        print(f"{n:6d}  {closed[k]:6d}   {k}")
    print(f"{len(cases):6d}  {sum(closed.values()):6d}   total")
    if show:
        for m in members.get(show, []):
            print(m)


if __name__ == "__main__":
    main()
