"""Columns: named numpy arrays, read as attributes or keys (``pts.x`` or ``pts["x"]``)."""


class Columns(dict):
    """A dict of equally long numpy arrays whose keys are also attributes."""

    def __getattr__(self, name):
        try:
            return self[name]
        except KeyError:
            raise AttributeError(name) from None

    def __dir__(self):
        return list(super().__dir__()) + list(self.keys())

    def __len__(self):  # number of keys, as a dict
        return dict.__len__(self)

    @property
    def rows(self) -> int:
        """Number of rows (length of the first column)."""
        for v in self.values():
            return len(v)
        return 0

    def __repr__(self):
        return "Columns(" + ", ".join(f"{k}[{len(v)}]" if hasattr(v, "__len__") else k for k, v in self.items()) + ")"
