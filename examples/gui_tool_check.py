"""The DroneCAN GUI tool against ``veronte4x simulate esc`` on the ``mcast:`` bus, headless.

A scripted check, run by hand (it needs Qt, which the test suite does not install): in a
virtual environment with the GUI tool (``pip install dronecan-gui-tool``, PyQt5 with it)::

    GUI_VENV/bin/python examples/gui_tool_check.py --veronte4x-python .venv/bin/python \\
        --screenshots shots/

It starts ``veronte4x simulate esc --nodes 21 -i mcast -c BUS`` with the other Python, then
the GUI tool itself (``dronecan_gui_tool.main.main``) on Qt's offscreen platform, and drives
it as a user would: types ``mcast:BUS`` into its setup dialog and presses OK, sets its local
node ID, waits for node 21 in its node list, opens the node's window and fetches every
parameter. It passes (exit 0) when the tool lists the node by name, has read its
parameters and has seen its ``uavcan.equipment.esc.Status``; it prints what it saw and saves
a screenshot of the main window and of the node's window. It gives up after ``--give-up``
seconds (exit 1).
"""

from __future__ import annotations

import argparse
import contextlib
import os
import subprocess
import sys
import time
from pathlib import Path
from typing import Any

NODE = 21
LOCAL_NODE = 127


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--veronte4x-python", default=sys.executable, help="runs veronte4x")
    parser.add_argument("--bus", type=int, default=0, help="the mcast bus number (0)")
    parser.add_argument("--screenshots", type=Path, default=Path("."), help="where PNGs go")
    parser.add_argument("--give-up", type=float, default=180.0, help="seconds (180)")
    options = parser.parse_args()
    os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
    sys.argv = sys.argv[:1]  # the GUI tool parses the command line when imported
    simulator = subprocess.Popen(
        [options.veronte4x_python, "-m", "veronte4x", "simulate", "esc", "--nodes", str(NODE),
         "-i", "mcast", "-c", str(options.bus)],
        stderr=subprocess.PIPE,
        text=True,
    )  # fmt: skip
    try:
        assert simulator.stderr is not None
        print(simulator.stderr.readline().strip())
        return _drive(options)
    finally:
        simulator.terminate()
        simulator.wait()


def _drive(options: argparse.Namespace) -> int:
    from dronecan_gui_tool import main as gui
    from dronecan_gui_tool.widgets.node_properties import ConfigParams
    from PyQt5.QtCore import QTimer
    from PyQt5.QtWidgets import QApplication, QComboBox, QPushButton

    end = time.monotonic() + options.give_up
    state: dict[str, Any] = {"result": 1}
    timers: list[QTimer] = []

    def setup_dialog() -> None:
        dialog = QApplication.activeModalWidget()
        if dialog is None or dialog.windowTitle() != "Application Setup":
            QTimer.singleShot(200, setup_dialog)
            return
        combo = dialog.findChild(QComboBox)
        combo.setEditText(f"mcast:{options.bus}")
        ok = next(b for b in dialog.findChildren(QPushButton) if b.text() == "OK")
        ok.click()
        timer = QTimer()
        timer.timeout.connect(step)
        timer.start(500)
        timers.append(timer)

    def step() -> None:
        window = next(
            (w for w in QApplication.topLevelWidgets() if isinstance(w, gui.MainWindow)), None
        )
        if time.monotonic() > end:
            print(f"gave up; got {sorted(state)}")
            QApplication.quit()
            return
        if window is None:
            return
        node = window._node
        if node.is_anonymous:
            window._local_node_widget._node_id_spinbox.setValue(LOCAL_NODE)
            window._local_node_widget._on_node_id_apply_clicked()
            return
        monitor = window._node_monitor_widget.monitor
        if "name" not in state:
            if NODE in monitor.get_all_node_id() and monitor.get(NODE).info is not None:
                state["name"] = monitor.get(NODE).info.name.decode()
                window._show_node_window(NODE)
            return
        properties = window._node_windows[NODE]
        params = properties.findChild(ConfigParams)
        if "fetching" not in state:
            state["fetching"] = True
            params._read_all_button.click()
            return
        rows = params._table.rowCount()
        if not rows or rows != state.get("rows"):  # still coming
            state["rows"] = rows
            return
        active = window._active_data_type_detector.get_names_of_active_messages()
        if "uavcan.equipment.esc.Status" not in active:
            return
        names = [params._table.item(row, 1).text() for row in range(rows)]
        print(f"node {NODE}: {state['name']}; {rows} parameters: {', '.join(names[:6])}, ...")
        print(f"messages the tool sees: {', '.join(sorted(active))}")
        options.screenshots.mkdir(parents=True, exist_ok=True)
        properties.resize(760, 820)  # every parameter in view
        window.grab().save(str(options.screenshots / "gui_tool_main.png"))
        properties.grab().save(str(options.screenshots / f"gui_tool_node_{NODE}.png"))
        print(f"screenshots in {options.screenshots}")
        state["result"] = 0
        QApplication.quit()

    setup_window = gui.run_setup_window

    def run_setup_window(*args: Any) -> Any:
        """The tool's own setup dialog, which `setup_dialog` fills in once it is up."""
        QTimer.singleShot(200, setup_dialog)
        return setup_window(*args)

    gui.run_setup_window = run_setup_window
    with contextlib.suppress(SystemExit):
        gui.main()
    return int(state["result"])


if __name__ == "__main__":
    sys.exit(main())
