"""The status of an `emb run` results file (libemb/results/results_writer.h): anything but
"success" means the run did not finish and the data end early; the plot scripts say so."""

import sys


def warn_if_unfinished(f, path):
    """Prints a warning to stderr unless the h5py file `f` holds a finished run."""
    def text(key):
        v = f.attrs.get(key)
        return v.decode() if isinstance(v, bytes) else v

    status = text("status")
    if status == "success":
        return
    note = ("the run was stopped without a word, e.g. killed, or is still going"
            if status == "running" else text("message") or "")
    t = f.attrs.get("t_reached")
    reached = f"; it reached t = {float(t):g} s" if t is not None else ""
    print(f"warning: '{path}' holds an unfinished run (status '{status}'"
          f"{': ' + note if note else ''}){reached}", file=sys.stderr)
