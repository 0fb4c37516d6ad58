"""lac.solve_batch: many G1 or G2 Hermite problems at once, locally on threads or on a Dask cluster."""
import numpy as np

from . import _lac

#: The per-row problem columns of each kind (other keys of ``data`` are options, scalars).
PROBLEM_COLUMNS = {
    "g1": ("p0", "theta0", "p1", "theta1", "alpha"),
    "g2": ("p0", "theta0", "kappa0", "p1", "theta1", "kappa1", "alpha"),
    "triangle": ("a0", "a1", "a2", "alpha"),
    "compound": ("a0", "a1", "a2", "alpha0", "alpha1", "r"),
}
POINT_COLUMNS = ("p0", "p1", "a0", "a1", "a2")
#: The result columns, named as the CLI's report keys (docs/cli.md "Schema").
RESULT_COLUMNS = ("status", "message", "length", "kappa0", "kappa1", "iterations", "evaluations", "seconds",
                  "error", "accept", "usable")
#: Further columns of some kinds: triangle and compound give Λ of segment 0 in user units.
EXTRA_COLUMNS = ("lambda0_user",)


def _kind(kind):
    k = {"g1_hermite": "g1", "g2_hermite": "g2"}.get(kind, kind)
    if k not in PROBLEM_COLUMNS:
        raise _lac.InputError(f"solve_batch: kind: '{kind}' is not one of g1 | g2 | triangle | compound")
    return k


def solve_batch(kind, data, *, threads=0, client=None, chunk_rows=None, **options):
    """Solve one problem per row and return lac.Columns named as the CLI schema.

    kind: "g1" (lac.g1_hermite: p0, theta0, p1, theta1, alpha), "g2" (lac.g2_hermite: p0, theta0,
    kappa0, p1, theta1, kappa1, alpha), "triangle" (001's control-triangle G1 segment, a0, a1, a2,
    alpha; `lac g1 --points ... --solver triangle`) or "compound" (lac.compound: a0, a1, a2, alpha0,
    alpha1, r). data: those columns as numpy arrays of n rows or scalars
    (broadcast); a point is (x, y), an (n, 2) array or a complex array. Other keys of data and the
    keyword options are the construction's options (solver=, integrator=, winding=, accept=, ...).

    Returns columns status, message, length, kappa0, kappa1, iterations, evaluations, seconds,
    error, accept, usable (arrays of n); triangle and compound also lambda0_user (Λ of segment 0). A row whose input is invalid has status "invalid_input"
    and its reason in message (as the CLI's --batch); invalid options raise lac.InputError.

    Locally the rows are solved on `threads` threads (0: every core) with the GIL released. With a
    dask.distributed `client` they are split into chunks of `chunk_rows` rows (default: about four
    chunks per worker) solved on the cluster's workers, each with `threads` threads; the results
    are identical to the local run.
    """
    k = _kind(kind)
    if client is None:
        out = _lac._solve_batch(k, dict(data), threads=threads, **options)
        out.pop("_wall_seconds", None)
        return _lac_columns(out)
    from .distributed import solve_batch_dask

    return solve_batch_dask(client, k, data, threads=threads, chunk_rows=chunk_rows, **options)


def _lac_columns(d):
    from ._columns import Columns

    return Columns({key: d[key] for key in RESULT_COLUMNS + EXTRA_COLUMNS if key in d})


def rows_of(kind, data):
    """Number of rows of `data` (1 when every column is a scalar); lac.InputError on mismatch."""
    n = None
    for key in PROBLEM_COLUMNS[_kind(kind)]:
        if key not in data:
            continue
        a = np.asarray(data[key])
        if key in POINT_COLUMNS:
            if np.iscomplexobj(a):
                r = a.shape[0] if a.ndim >= 1 else None
            else:
                r = a.shape[0] if a.ndim == 2 else None
        else:
            r = a.shape[0] if a.ndim >= 1 and a.size != 1 else None
        if r is not None:
            if n is not None and r != n:
                raise _lac.InputError(f"solve_batch: {key}: has {r} rows, other columns {n}")
            n = r
    return 1 if n is None else n


def slice_rows(kind, data, start, stop):
    """The rows [start, stop) of `data` (scalars and non-problem keys unchanged)."""
    n = rows_of(kind, data)
    out = {}
    for key, v in data.items():
        a = np.asarray(v) if key in PROBLEM_COLUMNS[_kind(kind)] else None
        if a is None:
            out[key] = v
        elif key in POINT_COLUMNS:
            out[key] = a[start:stop] if (np.iscomplexobj(a) and a.ndim >= 1) or a.ndim == 2 else v
        else:
            out[key] = a[start:stop] if a.ndim >= 1 and a.size != 1 and a.shape[0] == n else v
    return out
