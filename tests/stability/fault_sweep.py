#!/usr/bin/env python3
"""Fault sweep (standard library only): runs a command once with ASVGF_FAULT=count to learn how
many HAL calls of each kind it makes, then once per call with ASVGF_FAULT=<kind>:<n>, and checks
every run: either exit code 1 with a message on stderr naming the injected fault, or (a fault in
the teardown after the work was done, e.g. a destructor's wait) exit code 0 with exactly the files
of the unfaulted run; never a crash or an abort; and every file in the output folder whole (PNGs
decode with valid CRCs, EXRs start with the OpenEXR magic number, no `.partial` or `.tmp` file
left behind).

  fault_sweep.py OUT_DIR -- COMMAND...   COMMAND writes into OUT_DIR (cleared before each run)
  fault_sweep.py --files OUT_DIR -- COMMAND...
      the same over file output (ASVGF_FILE_FAULT: the n-th write, flush, sync, close or rename of
      the process fails, io/atomic_file.hpp): every run must exit 1 naming the file and the
      cause, with no half-written file and no temporary file left behind (a failed output is never
      an exit 0). Every write call fails once (each file, so each caller's handling); flush, sync,
      close and rename fail at their first and last call: every file goes through the one writer,
      whose clean-up after each of those operations is the same whichever file it writes.

Prints one line per kind and a total; exits 1 on the first failing run, naming it.
"""
import os
import re
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from png_chunks import png_chunks  # noqa: E402


def fail(message):
    print("fault_sweep: FAIL: " + message)
    sys.exit(1)


def png_whole(path):
    try:
        png_chunks(open(path, "rb").read())
        return True
    except ValueError:
        return False


def check_outputs(out_dir):
    """Returns the problem with the folder's files, or None."""
    for root, _, files in os.walk(out_dir):
        for name in files:
            path = os.path.join(root, name)
            if name.endswith(".partial") or name.endswith(".tmp"):
                return path + " is a half-written file left behind"
            if name.endswith(".png") and not png_whole(path):
                return path + " is not a whole PNG"
            if name.endswith(".exr"):
                head = open(path, "rb").read(8)
                if head[:4] != b"\x76\x2f\x31\x01" or os.path.getsize(path) < 64:
                    return path + " is not a whole OpenEXR file"
    return None


def files(out_dir):
    return sorted(os.path.relpath(os.path.join(root, name), out_dir)
                  for root, _, names in os.walk(out_dir) for name in names)


def run(command, out_dir, fault, variable="ASVGF_FAULT"):
    shutil.rmtree(out_dir, ignore_errors=True)
    env = dict(os.environ)
    env[variable] = fault
    return subprocess.run(command, env=env, capture_output=True, text=True, timeout=600)


def counted_run(command, out_dir, variable, label):
    """Runs the command unfaulted with `variable`=count; returns [(kind, calls)] from its `label` line."""
    counted = run(command, out_dir, "count", variable)
    if counted.returncode != 0:
        fail("the unfaulted run exits %d: %s" % (counted.returncode, counted.stderr.strip()[-400:]))
    match = re.search(r"^%s: (.*)" % label, counted.stderr, re.M)
    if not match:
        fail("the unfaulted run printed no " + label)
    return [(kind, int(n)) for kind, n in (item.split(" ") for item in match.group(1).split(", "))]


def sweep_files(out_dir, command):
    counts = counted_run(command, out_dir, "ASVGF_FILE_FAULT", "file fault counts")
    if sum(n for _, n in counts) == 0:
        fail("the unfaulted run wrote no file")
    total = 0
    for op, n in counts:
        calls = range(1, n + 1) if op == "write" else sorted({1, n}) if n else []
        for k in calls:
            fault = "%s:%d" % (op, k)
            r = run(command, out_dir, fault, "ASVGF_FILE_FAULT")
            where = "ASVGF_FILE_FAULT=%s %s" % (fault, " ".join(command))
            problem = check_outputs(out_dir)
            if problem:
                fail("%s: %s" % (where, problem))
            if r.returncode != 1:
                fail("%s exits %d (want 1): %s" % (where, r.returncode, (r.stderr or r.stdout).strip()[-600:]))
            if not re.search(r"/[^ ]+: cannot write \(%s\): \S" % op, r.stderr):
                fail("%s: no message names the file and the cause: %s" % (where, r.stderr.strip()[-600:]))
            total += 1
        print("fault_sweep: file %s: %d of %d calls failed, each cleanly" % (op, len(calls), n))
    print("fault_sweep: ok: %d faulted runs of %s" % (total, os.path.basename(command[0])))


def main():
    args = sys.argv[1:]
    files_mode = bool(args) and args[0] == "--files"
    if files_mode:
        args = args[1:]
    if len(args) < 3 or args[1] != "--":
        print(__doc__)
        sys.exit(2)
    out_dir, command = args[0], args[2:]
    if files_mode:
        sweep_files(out_dir, command)
        return
    counts = counted_run(command, out_dir, "ASVGF_FAULT", "fault counts")
    complete = files(out_dir)
    total = after_work = 0
    for kind, n in counts:
        late = 0
        for k in range(1, n + 1):
            fault = "%s:%d" % (kind, k)
            r = run(command, out_dir, fault)
            where = "ASVGF_FAULT=%s %s" % (fault, " ".join(command))
            problem = check_outputs(out_dir)
            if problem:
                fail("%s: %s" % (where, problem))
            if r.returncode == 0 and files(out_dir) == complete:
                late += 1  # injected in the teardown, after every output was written
            elif r.returncode != 1:
                fail("%s exits %d (want 1, or 0 with every output): %s"
                     % (where, r.returncode, (r.stderr or r.stdout).strip()[-600:]))
            elif "injected fault" not in r.stderr:
                fail("%s: no message names the injected fault: %s" % (where, r.stderr.strip()[-600:]))
            total += 1
        after_work += late
        print("fault_sweep: %s: %d calls, each failing cleanly (%d in the teardown after the work)" % (kind, n, late))
    print("fault_sweep: ok: %d faulted runs of %s, %d of them after the work was done"
          % (total, os.path.basename(command[0]), after_work))


if __name__ == "__main__":
    main()
