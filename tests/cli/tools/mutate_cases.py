"""Every numeric key of every case under cases/, set to each extreme value,
through `nspd check`: the refusal contract (core/status.h, issue 23).

    mutate_cases.py NSPD SOURCE_DIR [JOBS]

Each call must end in one of three ways:
  0  accepted;
  2  refused, stderr one line that names where ("FILE:LINE:COL: " or
     "--set KEY=VALUE: ") and what was expected ("expected"), or the memory
     refusal, which names --max-memory;
  1  a run-time failure with its reason ("nspd: error: " and text), never an
     internal error (a failure without a message, core/status.h).
Anything else (a crash, a sanitizer report, an empty message, a hang past
the timeout) is a failure of the test, printed with the command that gave
it. Every call runs with --max-memory 1 (MB): the reader and the size
estimate decide, and what they accept is refused before anything is built,
so thousands of calls take well under a minute; the checks that need the
model built (a PDDO shape matrix's condition, an image point's stencil) are
the fuzzers' and tests/cli/test_bad_input.sh's.
"""
import concurrent.futures
import glob
import math
import os
import re
import subprocess
import sys

import yaml

VALUES = ["0", "-1", "1e-300", "1e300", "1e11", "99999999999999999999", "nan", "[]"]
WHERE = re.compile(r"^(\S+:\d+:\d+: |--set \S+=.*?: )")


def numeric_paths(node, path):
    """Dotted --set paths of the numeric scalars under node."""
    if isinstance(node, dict):
        for key, value in node.items():
            yield from numeric_paths(value, path + [str(key)])
    elif isinstance(node, list):
        for index, value in enumerate(node):
            yield from numeric_paths(value, path + [str(index)])
    elif isinstance(node, (int, float)) and not isinstance(node, bool):
        if not (isinstance(node, float) and math.isnan(node)):
            yield ".".join(path)


def check(nspd, case, key, value):
    command = [nspd, "check", case, "--max-memory", "1", "--set", f"{key}={value}"]
    try:
        done = subprocess.run(command, capture_output=True, text=True, timeout=60)
    except subprocess.TimeoutExpired:
        return command, "no answer within 60 s"
    err = done.stderr.strip()
    if done.returncode == 0:
        return command, None
    if done.returncode == 2:
        if "\n" in err:
            return command, f"status 2 with more than one line: {err!r}"
        if "--max-memory" in err and "expected" in err:
            return command, None
        if not WHERE.match(err):
            return command, f"status 2 without FILE:LINE:COL or --set: {err!r}"
        if "expected" not in err:
            return command, f"status 2 without what was expected: {err!r}"
        return command, None
    if done.returncode == 1:
        reason = err[len("nspd: error: "):] if err.startswith("nspd: error: ") else ""
        if not reason.strip():
            return command, f"status 1 without a reason: {err!r}"
        if "internal error" in reason:
            return command, f"status 1, an internal error: {err!r}"
        return command, None
    return command, f"status {done.returncode}: {err[-400:]!r}"


def main():
    nspd, src = sys.argv[1], sys.argv[2]
    jobs = int(sys.argv[3]) if len(sys.argv) > 3 else os.cpu_count() or 1
    calls = []
    for case in sorted(glob.glob(os.path.join(src, "cases", "*.yaml"))):
        with open(case, encoding="utf-8") as f:
            tree = yaml.safe_load(f)
        for key in numeric_paths(tree, []):
            for value in VALUES:
                calls.append((case, key, value))
    failures = 0
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        for command, problem in pool.map(lambda c: check(nspd, *c), calls):
            if problem:
                failures += 1
                if failures <= 40:
                    print("FAIL", " ".join(command), "->", problem)
    cases = len({c for c, _, _ in calls})
    print(f"{len(calls)} calls ({cases} cases, {len(calls) // len(VALUES)} numeric keys, "
          f"{len(VALUES)} values each): {failures} broke the contract")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
