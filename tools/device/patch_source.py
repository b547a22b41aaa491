"""The probe builders' source patch (bvh_probe.sh, resident_probe.sh, timer_gaps_probe.sh): each
edit's old text must occur exactly once, so that a patch that no longer fits the sources fails
loudly instead of building an unpatched probe."""
import sys


def patch(tool, path, edits):
    s = open(path).read()
    for old, new in edits:
        if s.count(old) != 1:
            sys.exit("%s: %s no longer has '%s' once: update the patch" % (tool, path, old.strip()))
        s = s.replace(old, new)
    open(path, "w").write(s)


def patch_once(tool, path, old, new):
    patch(tool, path, [(old, new)])
