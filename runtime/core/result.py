"""The result of a simulation: named states and outputs, dense output, statistics."""
from __future__ import annotations

from functools import cached_property

import numpy as np

from ..engine import driver, finder
from . import display
from . import stability as _stability
from .errors import CamdynInputError, SimulationError


class Result:
    """Trajectory of one run.

    ``t`` and ``y`` hold the recorded points (every accepted step; a breakpoint
    appears twice, as left and right limit), ``f`` the slopes there.
    ``result["X"]`` gives a state or an output at those points;
    ``result.sample(times)`` evaluates everything at arbitrary times through
    the method's dense output.
    """

    def __init__(self, sim, p, out):
        # the model, method and cam laws are read off the Simulator when asked for: one
        # attribute set here instead of five, in a call whose fixed cost counts (Simulator.run)
        self._sim = sim
        self.p = p
        self._out = out
        # the warnings of a step near the stability boundary, set by Simulator.run
        self.warnings: list[str] = []

    @property
    def model(self):
        return self._sim.model

    @property
    def method(self):
        return self._sim.method

    @property
    def exact_segments(self) -> bool:
        """Whether intervals where the model is linear and time invariant were stepped over
        with their exact propagator (Simulator's ``exact_segments``)."""
        return self._sim.exact_segments

    @property
    def laws(self) -> dict:
        return self._sim.laws

    @property
    def law_codes(self) -> np.ndarray:
        return self._sim.law_codes

    @property
    def law_pars(self) -> np.ndarray:
        return self._sim.law_pars

    @property
    def dependent(self) -> tuple:
        """A constrained model's dependent coordinates in this run (Simulator's ``dependent``)."""
        return self._sim.dependent

    @property
    def part(self):
        """Their coordinate partition as the compiled code takes it (None: the declared one)."""
        return self._sim.part

    @cached_property
    def stability(self):
        """Fixed-step methods: the stability check the compiled loop made as it ran
        (camdyn.runtime.core.stability.Estimate, at the largest h |lambda|/b it saw); else None."""
        if self.method.adaptive:
            return None
        return _stability.from_loop(self.method.name, self.method.step, self._out)

    @property
    def stiff_from_T(self) -> float | None:
        """DP54: the time where Hairer's stiffness test (DOPRI5) first fired, else None."""
        t = getattr(self._out, "t_stiff", float("nan"))
        return None if t != t else float(t)

    @cached_property
    def stats(self) -> dict:
        """Steps, rejected steps, right-hand-side calls, wall time of the compiled loops; for
        the implicit methods also the Jacobians evaluated and the LU factorizations made; once
        a dense output left out of the run has been made (``record``), the calls of the run
        that made it (n_rhs_dense_output)."""
        o = self._out
        out = {"n_steps": o.n_steps, "n_rejected": o.n_rejected, "n_rhs": o.n_rhs,
               "n_events": o.n_events, "seconds": o.seconds}
        if getattr(o, "n_jac", 0):
            out.update(n_jac=o.n_jac, n_lu=o.n_lu)
        return out

    @cached_property
    def _rows(self) -> np.ndarray:
        return self._out.rows[:self._out.n]

    @property
    def _fills(self) -> bool:
        """Whether the run is DOP853's, whose left-out dense output is made step by step where
        it is wanted (ModelC.dense_fill), in place in the record."""
        return self.method.name == "dop853"

    def _fill(self, times=None) -> None:
        """Make the dense output a DOP853 run left out, of the steps ``times`` fall in (None:
        every step): each step made again from its recorded start, bit for bit the run's."""
        ns = len(self.state_names)
        calls = finder.fill(self.model.capsule, self.p, self.law_codes, self.law_pars,
                            self._rows, self.mode, ns, 4, times, part=self.part)
        self.count_dense_calls(calls)

    def count_dense_calls(self, calls: int) -> None:
        """Add right-hand-side calls made for the dense output after the run to the stats."""
        if calls:
            self.stats["n_rhs_dense_output"] = self.stats.get("n_rhs_dense_output", 0) + int(calls)

    @cached_property
    def record(self) -> np.ndarray:
        """The recorded rows [t, y, f, extra] (camdyn/runtime/engine/abi.pxd), one per point.

        Where a DOP853 run left its dense output out (Simulator's ``dense_output``), it is made
        here, step by step from the recorded starts; an RKN12 run runs again with it, from the
        same start: the same steps, now with their extra terms."""
        rows, ns = self._rows, len(self.state_names)
        if self._sim.integrator.dense or not np.isnan(rows[:, 1 + 2 * ns:]).any():
            return rows
        if self._fills:
            self._fill()
            return rows
        out = self._sim.integrator.run(self.p, self._sim.stops(self.p), rows.shape[0] + 1,
                                       rows[0, 1:1 + ns].copy(), dense=True)
        again = out.rows[:out.n]
        if out.status != 0 or again.shape != rows.shape or not np.array_equal(
                again[:, :1 + 2 * ns], rows[:, :1 + 2 * ns]):
            raise SimulationError(f"{self.model.name}: the run made again for its dense output "
                                  "did not take the same steps")
        self.count_dense_calls(out.n_rhs)
        return again

    @property
    def n_extra(self) -> int:
        """Dense-output terms beyond the cubic Hermite interpolant in each row: 1 for DP54, 4 for
        DOP853 and for every adaptive method that stepped over a linear segment exactly, else
        0 (camdyn/runtime/engine/abi.pxd, extra_terms; dense.pxd)."""
        return self._extra.shape[1] // len(self.state_names) if self._extra.shape[0] else 0

    @cached_property
    def mode(self) -> np.ndarray:
        """Modes in force from each recorded point on: cam segments, then force elements."""
        return self._out.modes[:self._out.n]

    def element_mode(self, name: str) -> np.ndarray:
        """Value names of the force-element mode ``name`` at the recorded points."""
        specs = self.model.manifest.get("modes", [])
        names = [m["name"] for m in specs]
        if name not in names:
            raise KeyError(f"{name!r} is not a mode of {self.model.name}; modes: {', '.join(names)}")
        k = names.index(name)
        col = self.mode[:, len(self.model.manifest["cam_instances"]) + k]
        return np.asarray(specs[k]["values"], dtype=object)[col]

    # views into the record rows [t, y, f, extra] (see camdyn/runtime/engine/abi.pxd)
    @cached_property
    def t(self) -> np.ndarray:
        return self._rows[:, 0]

    @cached_property
    def y(self) -> np.ndarray:
        return self._rows[:, 1:1 + len(self.state_names)]

    @cached_property
    def f(self) -> np.ndarray:
        """Slopes dy/dt at the recorded points (left limits at the end of an interval)."""
        ns = len(self.state_names)
        return self._rows[:, 1 + ns:1 + 2 * ns]

    @cached_property
    def _extra(self) -> np.ndarray:
        ns = len(self.state_names)
        if self._fills and self._rows.shape[1] > 1 + 2 * ns:
            return self._rows[:, 1 + 2 * ns:]     # made where sampled (sample)
        if self.record.shape[1] > 1 + 2 * ns:
            return self.record[:, 1 + 2 * ns:]
        return np.empty((0, ns))

    @cached_property
    def params(self) -> dict:
        return dict(zip(self.model.parameter_names, self.p.tolist()))

    @property
    def state_names(self) -> list[str]:
        return self.model.state_names

    @property
    def output_names(self) -> list[str]:
        return self.model.output_names

    @property
    def names(self) -> list[str]:
        return self.state_names + self.output_names

    @cached_property
    def outputs(self) -> dict:
        """Outputs at the recorded points (computed on first use, in C)."""
        out = driver.eval_outputs(self.model.capsule, self.p, self.law_codes, self.law_pars,
                                      self.t, self.y, self.mode, part=self.part)
        return {name: out[:, k] for k, name in enumerate(self.output_names)}

    def __getitem__(self, name: str) -> np.ndarray:
        if name in ("t", self.model.manifest["time"]["name"]):
            return self.t
        if name in self.state_names:
            return self.y[:, self.state_names.index(name)]
        if name in self.output_names:
            return self.outputs[name]
        raise KeyError(f"{name!r} is neither a state nor an output of {self.model.name}; "
                       f"known: {', '.join(self.names)}")

    @property
    def units(self) -> dict:
        """name -> unit of the time, every state and every output (the model's manifest)."""
        man = self.model.manifest
        units = {man["time"]["name"]: man["time"]["unit"]}
        units.update({s["name"]: s["unit"] for s in man["states"]})
        units.update({o["name"]: o["unit"] for o in man["outputs"]})
        return units

    def _describe(self) -> dict:
        """The run's settings and warnings, for the attributes of a table of it."""
        return {"model": self.model.name, "method": self.method.name, "warnings": list(self.warnings),
                "parameters": self.params, "stats": self.stats,
                "note": "the values of one run: each step within the method's tolerance; a "
                        "figure's error estimate comes from a second run (camdyn's answer "
                        "contract, runtime/measure/contract.py)"}

    @property
    def segment(self) -> np.ndarray:
        """The interval each recorded point belongs to, 0 on: a point at a breakpoint (a cam
        segment's end, an event) is recorded twice at the same time, as the left limit (the
        interval that ends there) and the right limit (the one that starts there)."""
        return np.concatenate([[0], np.cumsum(self.t[1:] == self.t[:-1])]).astype(np.int64)

    def to_pandas(self):
        """Every state and output at the recorded points as a pandas DataFrame indexed by the
        time, each time once: at a breakpoint, recorded twice as left and right limit, the
        frame keeps the right limit (the value from there on: an acceleration after the cam's
        jerk, not before), so that ``frame.loc[t]`` is one row and the index is unique.  Both
        limits are in ``result[name]`` and in :meth:`to_xarray` (its ``segment`` coordinate
        tells them apart).  ``.attrs`` holds the units, the model, the method, the parameters,
        the run's statistics and its warnings."""
        pd = display.need("pandas", "Result.to_pandas()")
        time_name = self.model.manifest["time"]["name"]
        # the last of the points at one time is its right limit
        right = np.append(self.t[1:] != self.t[:-1], True)
        frame = pd.DataFrame({n: np.asarray(self[n])[right] for n in self.names},
                             index=pd.Index(self.t[right], name=time_name))
        frame.attrs.update(units=self.units, **self._describe())
        return frame

    def to_xarray(self):
        """The run as an xarray Dataset over the recorded points (dimension ``point``, the time
        its coordinate; a breakpoint appears twice, as left and right limit, which the
        coordinate ``segment`` tells apart: :attr:`segment`), every state and output a variable
        with its unit and description as attributes."""
        xr = display.need("xarray", "Result.to_xarray()")
        man = self.model.manifest
        docs = {d["name"]: d.get("doc", "") for d in [*man["states"], *man["outputs"]]}
        units = self.units
        time_name = man["time"]["name"]
        data = {n: ("point", np.asarray(self[n]), {"units": units[n], "description": docs[n]})
                for n in self.names}
        attrs = self._describe()
        attrs = {**{k: v for k, v in attrs.items() if k not in ("parameters", "stats", "warnings")},
                 "warnings": "; ".join(self.warnings) or "none",
                 **{f"parameter_{k}": v for k, v in attrs["parameters"].items()},
                 **{f"stat_{k}": v for k, v in attrs["stats"].items()}}
        coords = {time_name: ("point", self.t, {"units": units[time_name]}),
                  "segment": ("point", self.segment, {
                      "description": "the interval of the point, 0 on: at a breakpoint the "
                                     "left limit is in the interval that ends there"})}
        return xr.Dataset(data, coords=coords, attrs=attrs)

    def _repr_html_(self) -> str:
        man = self.model.manifest
        stats = self.stats
        head = f"Run of {self.model.name} with {self.method.name}: {stats['n_steps']} steps, " \
               f"{man['time']['name']} from {self.t[0]:g} to {self.t[-1]:g} {man['time']['unit']}"
        params = display.table(["parameter", "value", "unit"],
                               [[k, v, next((p["unit"] for p in man["parameters"] if p["name"] == k), "")]
                                for k, v in self.params.items()])
        runs = display.table(list(stats), [list(stats.values())])
        return display.page(head, runs, params, self._no_figures(),
                            display.warnings_block(self.warnings), display.picture(self.chart()))

    def _no_figures(self) -> str:
        """What a bare run shows in place of figures: that it has none with an error estimate,
        and the call that gives them (the answer contract: a figure comes with its estimate,
        which takes a second run one notch tighter)."""
        import html

        call = f"answer(resolve({self.model.name!r}, params={self.params!r}))"
        return ("<p>figures: none here. A Result is one run's values, each step within the "
                "method's tolerance, which bounds no figure's error. The figures (U0, U0'', "
                "the state at the end, ...) each with its error estimate and the estimate's "
                "parts come from <code>from camdyn.runtime.measure.contract import answer; "
                "from camdyn.runtime.targets.resolve import resolve; "
                f"{html.escape(call)}</code> (add the run's settings: t_end, method, rtol, "
                "law, ...).</p>")

    def chart(self, names=None, note: str = "one run's values; figures with error estimates: "
                                             "camdyn.runtime.measure.contract.answer"):
        """``names`` (default: the model's residual acceleration and error, else its first two
        states) against time, side by side: a matplotlib Figure made without pyplot."""
        from matplotlib.figure import Figure

        man = self.model.manifest
        residual = man.get("residual") or {}
        shown = list(names or [n for n in (residual.get("acceleration"), residual.get("error"))
                               if n] or self.state_names[:2])
        fig = Figure(figsize=(7, 3.2))
        axes = fig.subplots(1, len(shown), squeeze=False)[0]
        units = self.units
        time_name = man["time"]["name"]
        for ax, name in zip(axes, shown):
            ax.plot(self.t, self[name], lw=0.8)
            ax.set_xlabel(f"{time_name} ({units[time_name]})")
            ax.set_ylabel(f"{name} ({units[name]})")
            ax.grid(alpha=0.3)
        fig.text(0.01, 0.01, note, fontsize=7)
        fig.tight_layout(rect=(0, 0.06, 1, 1))
        return fig

    def sample(self, times) -> dict:
        """States and outputs at ``times`` (dense output), as a dict of arrays."""
        tq = np.ascontiguousarray(np.atleast_1d(np.asarray(times, dtype=float)))
        if tq.size and (tq.min() < self.t[0] or tq.max() > self.t[-1]):
            raise CamdynInputError(
                f"sample times must lie in [{self.t[0]:g}, {self.t[-1]:g}]")
        if self._fills and tq.size:
            self._fill(tq)
        Y, idx = driver.dense_eval(self.t, self.y, self.f, self._extra, tq)
        modes = np.ascontiguousarray(self.mode[idx]) if self.mode.shape[1] else None
        out = driver.eval_outputs(self.model.capsule, self.p, self.law_codes, self.law_pars,
                                      tq, Y, modes, part=self.part)
        res = {"t": tq}
        res.update({name: Y[:, k] for k, name in enumerate(self.state_names)})
        res.update({name: out[:, k] for k, name in enumerate(self.output_names)})
        return res
