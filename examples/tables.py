"""A notebook session on a whole flight with the columnar engine: load, filter, plot.

Usage: python examples/tables.py [CAPTURE] [PLOT.png]

Needs the ``arrow``, ``pandas`` and ``plot`` extras. Run ``python examples/make_capture.py``
first to make ``examples/flight.log``.
"""

from __future__ import annotations

import sys
from datetime import timedelta
from pathlib import Path
from typing import Any

import pyarrow.compute as pc
from matplotlib.figure import Figure

from veronte4x import capture

HERE = Path(__file__).parent


def main(path: str, plot_path: str) -> None:
    """Load every table, filter by type, node and time, plot ESC telemetry and selection."""
    tables = capture.read_tables(path)  # one Arrow table per message type
    for kind, table in sorted(tables.items()):
        print(f"{kind:24} {table.num_rows:>8} rows")

    start = min(pc.min(table["timestamp"]).as_py() for table in tables.values())
    esc = tables["EscStatus"]
    node = esc.filter(pc.equal(esc["node_id"], 20))  # one ESC, filtered in Arrow
    window = node.filter(
        pc.and_(
            pc.greater_equal(node["timestamp"], start + timedelta(seconds=5)),
            pc.less(node["timestamp"], start + timedelta(seconds=15)),
        )
    ).to_pandas()
    print(f"\nESC node 20, 5-15 s from the start: {len(window)} rows")
    print(window[["voltage", "current", "rpm"]].describe().round(2).to_string())

    status = tables["Status"].to_pandas()
    switches = status[status.selected.ne(status.selected.shift())]
    print("\nSelected autopilot changes (UTC, and seconds from the start):")
    for row in switches.itertuples():
        since = (row.timestamp - start).total_seconds()
        print(f"  {row.timestamp:%H:%M:%S.%f}  {since:8.3f}  {row.selected_name}")

    def seconds(times: Any) -> Any:
        """Times as seconds from the start, for the x axis."""
        return (times - start) / timedelta(seconds=1)

    figure = Figure(figsize=(9, 6), layout="constrained")
    rpm, voltage, selected = figure.subplots(3, 1, sharex=True)
    for node_id, rows in esc.to_pandas().groupby("node_id"):
        time = seconds(rows.timestamp)
        rpm.plot(time, rows.rpm, label=f"node {node_id}", linewidth=0.8)
        voltage.plot(time, rows.voltage, linewidth=0.8)
    rpm.set_ylabel("rpm")
    rpm.legend(loc="upper right", fontsize="small")
    voltage.set_ylabel("voltage (V)")
    selected.step(seconds(status.timestamp), status.selected + 1, where="post")
    selected.set_yticks([1, 2, 3, 4], ["AP1", "AP2", "AP3", "external"])
    selected.set_ylabel("selected")
    selected.set_xlabel(f"time (s) from {start:%Y-%m-%d %H:%M:%S} UTC")
    figure.suptitle("ESC telemetry and the selected autopilot")
    figure.savefig(plot_path, dpi=100)
    print(f"\nplot saved to {plot_path}")


if __name__ == "__main__":
    main(
        sys.argv[1] if len(sys.argv) > 1 else str(HERE / "flight.log"),
        sys.argv[2] if len(sys.argv) > 2 else str(HERE / "tables.png"),
    )
