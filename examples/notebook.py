"""What a notebook does with a capture: records, a DataFrame, scores, a plot.

Usage: python examples/notebook.py [CAPTURE] [PLOT.png]

Needs the ``pandas`` and ``plot`` extras. Run ``python examples/make_capture.py`` first
to make ``examples/flight.log``.
"""

from __future__ import annotations

import sys
from pathlib import Path

from veronte4x import capture
from veronte4x.capture.plot import arbitration_timeline

HERE = Path(__file__).parent


def main(path: str, plot_path: str) -> None:
    """Load the capture, summarise it, save the arbitration plot."""
    records = list(capture.read(path))
    print(capture.stats(records).report())

    frame = capture.to_dataframe(records)
    frame["time"] = frame.timestamp - frame.timestamp.min()  # seconds from the start
    scores = frame[frame.message == "Score"].pivot_table(
        index="time", columns="autopilot", values="score"
    )
    print("\nScores per autopilot (first rows):")
    print(scores.head().to_string())

    esc = frame[frame.message == "EscStatus"].groupby("esc_index")[["rpm", "current"]].mean()
    print("\nMean rpm and current per ESC:")
    print(esc.round(1).to_string())

    status = frame[frame.message == "Status"]
    changed = status.selected.ne(status.selected.shift()).fillna(True).astype(bool)
    switches = status[changed]
    print("\nSelected autopilot over time:")
    print(switches[["time", "selected", "alive_0", "alive_1", "alive_2"]].to_string())

    arbitration_timeline(records).savefig(plot_path)
    print(f"\nplot saved to {plot_path}")


if __name__ == "__main__":
    main(
        sys.argv[1] if len(sys.argv) > 1 else str(HERE / "flight.log"),
        sys.argv[2] if len(sys.argv) > 2 else str(HERE / "arbitration.png"),
    )
