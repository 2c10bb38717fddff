"""``veronte4x esc``: find, configure, update and spin Vertiq ESCs on a live DroneCAN bus.

Every action opens the bus with python-can's options, runs the ground-station client
(`veronte4x.client.bus.BusClient`) and prints for people, or JSON with ``--json``. Errors are
one line on standard error with the documented exit code; ``spin`` sends zero throttle on
every way out.
"""

from __future__ import annotations

import argparse
import json
import random
import signal
import sys
import time
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, Any, TypeVar

from veronte4x.capture.busmap import BusMap
from veronte4x.cli import allocate
from veronte4x.cli.exit_codes import (
    EXIT_FINDINGS,
    EXIT_INTERRUPTED,
    EXIT_NO_ANSWER,
    EXIT_OK,
    EXIT_USAGE,
)
from veronte4x.cli.fleet import (
    OWN_ID_ADVICE,
    each,
    error_text,
    exit_code,
    node_list,
    resolve,
    total,
)
from veronte4x.cli.options import add_bus_options, add_dsdl_option, bus_settings
from veronte4x.client import indices, operations, paramfile, parmfile
from veronte4x.client.commander import STOP_REPEATS
from veronte4x.client.errors import (
    ClientError,
    InvalidRequestError,
    NoResponseError,
)
from veronte4x.client.firmware import (
    MAX_IMAGE_SIZE,
    FirmwareOptions,
    Phase,
    UpdateProgress,
    check_image,
    image_crc,
)
from veronte4x.client.indices import EscIndexError, OwnNodeIdError
from veronte4x.client.nodes import NodeEntry
from veronte4x.client.operations import Operation
from veronte4x.client.params import ParameterInfo, plain
from veronte4x.client.protocol import DEFAULT_NODE_ID
from veronte4x.client.spin import (
    DEFAULT_SILENCE,
    AllowUnknown,
    Spin,
    SpinArgumentError,
    SpinStoppedError,
)
from veronte4x.dronecan.messages import (
    GetNodeInfoResponse,
    IntegerValue,
    Opcode,
    SoftwareVersionFlag,
)
from veronte4x.errors import EncodeError
from veronte4x.node.requests import DEFAULT_RETRIES, DEFAULT_TIMEOUT
from veronte4x.words import counted

if TYPE_CHECKING:
    from veronte4x.client.bus import BusClient

Action = Callable[["BusClient", argparse.Namespace], int]


def add_parser(commands: Any) -> None:
    """Register the command and its actions."""
    parser = commands.add_parser(
        "esc", help="find, configure, update and spin Vertiq ESCs (DroneCAN, live bus)"
    )
    actions = parser.add_subparsers(required=True, metavar="ACTION")

    def action(name: str, help: str, run: Action) -> argparse.ArgumentParser:
        sub: argparse.ArgumentParser = actions.add_parser(name, help=help, description=help)
        sub.set_defaults(run=_runner(run), bus_map=None)
        return sub

    nodes = action("nodes", "list the nodes on the bus, from their NodeStatus", _nodes)
    nodes.add_argument(
        "--timeout", type=float, default=1.1, metavar="S", help="seconds to listen (1.1)"
    )
    _options(nodes, timeout=False)

    info = action("info", "GetNodeInfo: name, versions, image CRC, unique id", _info)
    _node(info)

    params = action("params", "every parameter: name, value, default, range", _params)
    _node(params)
    params.add_argument(
        "--save",
        metavar="FILE",
        help="write every parameter of each node, with its name and unique id, to a TOML file",
    )

    apply = action(
        "apply",
        "restore parameters saved by params --save or the DroneCAN GUI tool: diff, check, set, "
        "read back, save",
        _apply,
    )
    apply.add_argument(
        "file",
        help="a file written by: veronte4x esc params NODES --save FILE; or a .parm file of "
        "one node, saved by the DroneCAN GUI tool",
    )
    apply.add_argument("nodes", type=node_list, metavar="NODES", help=_NODES_HELP)
    apply.add_argument("--dry-run", action="store_true", help="show what would change; send no set")
    apply.add_argument(
        "--from",
        dest="source",
        type=node_id,
        metavar="NODE",
        help="apply the file's parameters of NODE (e.g. onto a replacement with another id)",
    )
    _allow_shared(apply)
    _allow_unknown(apply, "apply an esc_index")
    _options(apply)

    get = action("get", "read one parameter by name (or by index with --by-index)", _get)
    _node(get)
    get.add_argument("name", help="parameter name, e.g. esc_index (an index with --by-index)")
    _by_index(get)

    set_ = action("set", "set one parameter by name (range checked first)", _set)
    _node(set_)
    set_.add_argument("name", help="parameter name (an index with --by-index)")
    set_.add_argument("value", help="new value, of the parameter's type")
    _by_index(set_)
    _allow_shared(set_)
    _allow_unknown(set_, "set esc_index")

    save = action("save", "save the parameters to non-volatile storage (ExecuteOpcode)", _save)
    _node(save)

    erase = action("erase", "erase the stored parameters back to defaults (ExecuteOpcode)", _erase)
    _node(erase)

    restart = action("restart", "restart the node (RestartNode with the magic number)", _restart)
    _node(restart)
    restart.add_argument(
        "--bootloader", action="store_true", help="Vertiq: restart into the ST bootloader"
    )

    update = action(
        "update", "update the firmware: the node pulls the image via file.Read", _update
    )
    update.add_argument("nodes", type=node_list, metavar="NODES", help=_NODES_HELP)
    update.add_argument("firmware", help="firmware image file")
    update.add_argument(
        "--force", action="store_true", help="update a node that reports the image's CRC already"
    )
    update.add_argument("--path", help="name the node is told to read (default: the file name)")
    update.add_argument("--start-timeout", type=float, default=10.0, metavar="S")
    update.add_argument("--read-timeout", type=float, default=5.0, metavar="S")
    update.add_argument("--restart-timeout", type=float, default=30.0, metavar="S")
    update.add_argument(
        "--max-image-size",
        type=int,
        default=MAX_IMAGE_SIZE,
        metavar="BYTES",
        help=f"refuse a larger image before sending anything ({MAX_IMAGE_SIZE})",
    )
    _options(update)

    spin = action("spin", "spin motors with RawCommand at a rate (needs --yes)", _spin)
    spin.add_argument(
        "nodes", type=node_list, nargs="+", metavar="NODES", help="node ids or ranges (not all)"
    )
    spin.add_argument("--throttle", type=float, required=True, help="fraction in [-1, 1]")
    spin.add_argument("--duration", type=float, required=True, metavar="S", help="seconds")
    spin.add_argument("--rate", type=float, default=50.0, help="commands per second (50)")
    spin.add_argument(
        "--watchdog", type=float, default=0.5, metavar="S", help="zero throttle after S (0.5)"
    )
    spin.add_argument(
        "--silence",
        type=float,
        default=DEFAULT_SILENCE,
        metavar="S",
        help="stop every motor when a node sends no esc.Status or NodeStatus for S "
        f"({DEFAULT_SILENCE:g})",
    )
    spin.add_argument(
        "--max-temperature",
        type=float,
        metavar="DEG_C",
        help="stop every motor when an esc.Status temperature exceeds this, in degrees C",
    )
    spin.add_argument(
        "--max-current",
        type=float,
        metavar="A",
        help="stop every motor when an esc.Status current exceeds this, in amperes",
    )
    spin.add_argument("--yes", action="store_true", help="confirm: this moves motors")
    _allow_unknown(spin, "spin")
    _options(spin)

    allocator = action("allocate", allocate.HELP, allocate.run)
    allocate.add_arguments(allocator)
    _options(allocator)


def node_id(text: str) -> int:
    """A DroneCAN node id from the command line, 1..127 (argparse type)."""
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a node id (1..127)") from None
    if not 1 <= value <= 127:
        raise argparse.ArgumentTypeError(f"node id {value} is out of range: 1..127")
    return value


def _by_index(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--by-index",
        action="store_true",
        help="NAME is the parameter's index (discovery order; may change with the firmware)",
    )


def _parameter(args: argparse.Namespace) -> tuple[str | None, int | None]:
    """The parameter's name, or its index with ``--by-index``: never one for the other.

    Raises:
        InvalidRequestError: An index that is not a whole number, or a name that looks like
            an index without ``--by-index``.
    """
    if args.by_index:
        if not args.name.isdigit():
            raise InvalidRequestError(f"--by-index needs a whole number, not {args.name!r}")
        return None, int(args.name)
    if args.name.isdigit():
        raise InvalidRequestError(
            f"{args.name!r} is an index, not a parameter name; add --by-index to use it as one"
        )
    return args.name, None


_NODES_HELP = "node id, list or range: 21, 21,22, 21-28, or all (those that answer)"


def _node(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("nodes", type=node_list, metavar="NODES", help=_NODES_HELP)
    _options(parser)


def _options(parser: argparse.ArgumentParser, *, timeout: bool = True) -> None:
    add_bus_options(parser)
    add_dsdl_option(parser)
    parser.add_argument(
        "--node-id",
        type=node_id,
        default=DEFAULT_NODE_ID,
        help=f"this tool's node id ({DEFAULT_NODE_ID}); give each tool on the bus its own",
    )
    if timeout:
        parser.add_argument(
            "--timeout",
            type=float,
            default=DEFAULT_TIMEOUT,
            metavar="S",
            help=f"seconds to wait for each answer ({DEFAULT_TIMEOUT:g})",
        )
    parser.add_argument(
        "--retries", type=int, default=DEFAULT_RETRIES, help=f"retries ({DEFAULT_RETRIES})"
    )
    parser.add_argument("--json", action="store_true", help="JSON on standard output")


def _error(message: str) -> None:
    print(f"veronte4x: {message}", file=sys.stderr)


def _runner(action: Action) -> Callable[[argparse.Namespace, BusMap | None], int]:
    def run(args: argparse.Namespace, bus_map: BusMap | None) -> int:
        from veronte4x.cli.buses import open_bus, require_bus_packages

        require_bus_packages(bus_settings(args), "veronte4x esc")
        import can

        from veronte4x.client.bus import BusClient

        bus = open_bus(**bus_settings(args))
        try:
            client = BusClient(
                bus,
                args.node_id,
                timeout=getattr(args, "timeout", 1.0),
                retries=args.retries,
                # A run right after another must not repeat its last transfer ids.
                first_transfer_id=random.randrange(32),
            )
            return action(client, args)
        except (ClientError, EncodeError) as error:
            _error(str(error))
            return exit_code(error)
        except KeyboardInterrupt:
            _error("interrupted")
            return EXIT_INTERRUPTED
        except can.CanError as error:
            _error(f"the CAN bus failed: {error}")
            return EXIT_USAGE
        finally:
            bus.shutdown()

    return run


def _print_json(data: Any) -> None:
    print(json.dumps(data))


# -- nodes and info ------------------------------------------------------------------------


def _entry(entry: NodeEntry, now: float, name: str | None, own: int) -> dict[str, Any]:
    return {
        "node_id": entry.node_id,
        "name": name,
        "health": _name(entry.health),
        "mode": _name(entry.mode),
        "sub_mode": entry.sub_mode,
        "vendor_specific_status_code": entry.vendor_specific_status_code,
        "uptime_sec": entry.uptime_sec,
        "last_seen_sec_ago": round(now - entry.last_seen, 3),
        "conflict": _CONFLICT if entry.node_id == own else None,
    }


_CONFLICT = "uses this tool's node id"
"""What ``esc nodes`` says of a node that uses the tool's own node id."""


def _name(value: Any) -> Any:
    return getattr(value, "name", value)


def _nodes(client: BusClient, args: argparse.Namespace) -> int:
    found = client.discover(args.timeout)
    now = client.clock()
    own = client.protocol.node_id
    names = {e.node_id: None if e.node_id == own else _node_name(client, e.node_id) for e in found}
    if args.json:
        _print_json([_entry(e, now, names[e.node_id], own) for e in found])
    if not found:
        _error(
            f"no node on the bus within {args.timeout:g} s; "
            "check --interface, --channel and --bitrate"
        )
        return EXIT_NO_ANSWER
    if not args.json:
        width = max(len(n or "?") for n in names.values())
        digits = max(7, *(len(str(e.uptime_sec)) for e in found))  # uint32: up to 10
        print(
            f"{'node':>4}  {'name':<{width}}  {'health':<8}  {'mode':<15}  "
            f"{'uptime':>{digits + 2}}  {'seen':>11}  vendor"
        )
        for e in found:
            print(
                f"{e.node_id:>4}  {names[e.node_id] or '?':<{width}}  {_name(e.health):<8}  "
                f"{_name(e.mode):<15}  {e.uptime_sec:>{digits}} s  "
                f"{now - e.last_seen:>5.1f} s ago  {e.vendor_specific_status_code:#06x}"
                + (f"  conflict: {_CONFLICT}" if e.node_id == own else "")
            )
    if any(e.node_id == own for e in found):
        _error(f"{OwnNodeIdError(own)}; {OWN_ID_ADVICE}")
    return EXIT_OK


def _node_name(client: BusClient, node_id: int) -> str | None:
    """The node's GetNodeInfo name, or None if it does not answer (as the GUI tool shows)."""
    try:
        return client.node_info(node_id).name.decode("utf-8", "replace")
    except NoResponseError:
        return None


def _info_dict(node_id: int, info: GetNodeInfoResponse) -> dict[str, Any]:
    sw, hw = info.software_version, info.hardware_version
    flags = sw.optional_field_flags
    return {
        "node_id": node_id,
        "name": info.name.decode("utf-8", "replace"),
        "health": _name(info.status.health),
        "mode": _name(info.status.mode),
        "uptime_sec": info.status.uptime_sec,
        "software_version": {
            "major": sw.major,
            "minor": sw.minor,
            "vcs_commit": sw.vcs_commit if flags & SoftwareVersionFlag.VCS_COMMIT else None,
            "image_crc": f"{sw.image_crc:#018x}" if flags & SoftwareVersionFlag.IMAGE_CRC else None,
        },
        "hardware_version": {
            "major": hw.major,
            "minor": hw.minor,
            "unique_id": hw.unique_id.hex(),
            "certificate_of_authenticity": hw.certificate_of_authenticity.hex(),
        },
    }


def _info(client: BusClient, args: argparse.Namespace) -> int:
    return each(client, args, operations.node_info, _info_text, _info_dict)


def _info_text(node: int, info: GetNodeInfoResponse) -> str:
    data = _info_dict(node, info)
    sw, hw = data["software_version"], data["hardware_version"]
    return "\n".join(
        [
            f"node {node}: {data['name']}",
            f"  status    health {data['health']}, mode {data['mode']}, "
            f"uptime {data['uptime_sec']} s",
            f"  software  {sw['major']}.{sw['minor']}, vcs commit "
            f"{'-' if sw['vcs_commit'] is None else format(sw['vcs_commit'], '#010x')}, "
            f"image CRC {sw['image_crc'] or '-'}",
            f"  hardware  {hw['major']}.{hw['minor']}, unique id {hw['unique_id']}, "
            f"certificate of authenticity {hw['certificate_of_authenticity'] or '(none)'}",
        ]
    )


# -- parameters --------------------------------------------------------------------------------


def _range(p: ParameterInfo) -> str:
    low, high = plain(p.minimum), plain(p.maximum)
    if low is None and high is None:
        return "-"
    return f"{'' if low is None else low}..{'' if high is None else high}"


def _text(value: Any) -> str:
    """A parameter's value or default for people: ``-`` when the node reports none."""
    shown = plain(value)
    return "-" if shown is None else str(shown)


def _show(p: ParameterInfo) -> str:
    return f"{p.name} = {_text(p.value)} (default {_text(p.default)}, range {_range(p)})"


def _params(client: BusClient, args: argparse.Namespace) -> int:
    if args.save:
        return _save_file(client, args)
    return each(
        client,
        args,
        operations.list_params,
        lambda node, found: _table(found, None if args.nodes.single else node),
        lambda node, found: (
            [p.as_dict() for p in found]
            if args.nodes.single
            else {"parameters": [p.as_dict() for p in found]}
        ),
    )


def _table(found: list[ParameterInfo], node: int | None) -> str:
    width = max((len(p.name) for p in found), default=4)
    lines = [] if node is None else [f"node {node}:"]
    lines.append(f"{'index':>5}  {'name':<{width}}  {'value':>10}  {'default':>10}  range")
    for p in found:
        lines.append(
            f"{p.index:>5}  {p.name:<{width}}  {_text(p.value):>10}  "
            f"{_text(p.default):>10}  {_range(p)}"
        )
    return "\n".join(lines)


def _save_file(client: BusClient, args: argparse.Namespace) -> int:
    nodes = resolve(client, args.nodes)
    tasks = client.run_all([operations.read_node(node) for node in nodes])
    failed = [(node, t.error) for node, t in zip(nodes, tasks, strict=True) if t.error]
    for node, error in failed:
        _error(f"node {node}: {error_text(node, error)}")
    if failed:
        _error(f"nothing written to {args.save}: {total(len(nodes), [n for n, _ in failed])}")
        return exit_code(failed[0][1])
    saved = [t.result() for t in tasks]
    stamp = time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime())
    text = paramfile.dumps(saved, f"veronte4x esc params --save, {stamp}")
    Path(args.save).write_text(text, encoding="utf-8")
    count = sum(len(n.parameters) for n in saved)
    summary = {"file": args.save, "nodes": [n.node_id for n in saved], "parameters": count}
    if args.json:
        _print_json(summary)
    else:
        print(f"saved {count} parameter{'s' * (count != 1)} of node{'s' * (len(saved) > 1)} "
              f"{', '.join(str(n.node_id) for n in saved)} to {args.save}")  # fmt: skip
    return EXIT_OK


def _one_node(args: argparse.Namespace) -> str:
    return "" if args.nodes.single else "node {node}: "


def _get(client: BusClient, args: argparse.Namespace) -> int:
    name, index = _parameter(args)
    prefix = _one_node(args)
    return each(
        client,
        args,
        lambda node: operations.get_param(node, name, index=index),
        lambda node, p: prefix.format(node=node) + _show(p),
        lambda node, p: _param_json(p),
    )


def _param_json(parameter: ParameterInfo) -> dict[str, Any]:
    """A parameter read or set, for ``--json``: its index only where it is known (a
    parameter named is read by name, and GetSet answers without its index)."""
    data = parameter.as_dict()
    if parameter.index is None:
        del data["index"]
    return data


def _set(client: BusClient, args: argparse.Namespace) -> int:
    name, index = _parameter(args)
    prefix = _one_node(args)
    nodes = resolve(client, args.nodes)
    if _names_esc_index(client, nodes, name, index):
        try:
            wanted = int(args.value, 0)  # as ParameterInfo.parse reads an integer
        except ValueError:
            pass  # not a whole number: the set refuses it, naming the node
        else:
            survey = client.run(indices.survey(client.protocol, nodes))
            changes = {n: wanted for n in nodes if survey.indices.get(n) != wanted}
            _check_indices(args, changes, survey)
    return each(
        client,
        args,
        lambda node: operations.set_param(node, name, args.value, index=index),
        lambda node, p: prefix.format(node=node) + _show(p),
        lambda node, p: _param_json(p),
        nodes,
    )


def _names_esc_index(
    client: BusClient, nodes: list[int], name: str | None, index: int | None
) -> bool:
    """Whether the parameter set is ``esc_index``: by its name, or by what the nodes call
    the parameter at ``index``."""
    if name is not None:
        return name == indices.ESC_INDEX
    reads = client.run_all([operations.get_param(node, index=index) for node in nodes])
    return any(t.error is None and t.result().name == indices.ESC_INDEX for t in reads)


def _check_indices(
    args: argparse.Namespace, changes: dict[int, int], survey: indices.IndexSurvey
) -> None:
    """Refuse ``changes`` of esc_index that another node's index forbids (`check_changes`),
    unless the options allow it.

    Raises:
        InvalidRequestError: One line with what to add to do it anyway.
    """
    try:
        indices.check_changes(
            changes,
            survey,
            allow_shared=args.allow_shared_index,
            allow_unknown=_unknown_allowed(args, survey),
        )
    except EscIndexError as error:
        advice = _unknown_advice(error)
        if error.shared:
            advice.append("add --allow-shared-index to give it anyway")
        raise InvalidRequestError(error.line(*advice)) from None


def _allow_shared(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--allow-shared-index",
        action="store_true",
        help="give a node an esc_index that another node on the bus has too (RawCommand "
        "then turns both); by default it is refused",
    )


def _done(client: BusClient, args: argparse.Namespace, make: Any, what: str) -> int:
    return each(
        client,
        args,
        make,
        lambda node, _: f"node {node}: {what}",
        lambda node, _: {"node_id": node, "ok": True},
    )


def _save(client: BusClient, args: argparse.Namespace) -> int:
    return _done(
        client, args, lambda node: operations.opcode(node, Opcode.SAVE), "parameters saved"
    )


def _erase(client: BusClient, args: argparse.Namespace) -> int:
    return _done(
        client,
        args,
        lambda node: operations.opcode(node, Opcode.ERASE),
        "stored parameters erased (defaults after a restart)",
    )


def _restart(client: BusClient, args: argparse.Namespace) -> int:
    return _done(
        client,
        args,
        lambda node: operations.restart(node, bootloader=args.bootloader),
        "restarting" + (" into the bootloader" if args.bootloader else ""),
    )


# -- firmware update ---------------------------------------------------------------------------


MAX_PATH = 200
"""Bytes of a path in a file request (DSDL ``uavcan.protocol.file.Path``: ``uint8[<=200]``)."""


def read_image(file: str, max_size: int) -> bytes:
    """The firmware image in ``file``, reading no more than one byte past ``max_size``.

    Raises:
        InvalidRequestError: The image is empty or larger than ``max_size``.
        OSError: The file cannot be read.
    """
    with open(file, "rb") as stream:
        image = stream.read(max_size + 1)
    if len(image) > max_size:
        raise InvalidRequestError(
            f"{file} has more than {counted(max_size, 'byte')}, the firmware image limit; "
            "nothing was sent (raise --max-image-size if the image is right)"
        )
    check_image(image, max_size)
    return image


def _update(client: BusClient, args: argparse.Namespace) -> int:
    image = read_image(args.firmware, args.max_image_size)
    path = args.path or Path(args.firmware).name
    if len(path.encode("utf-8")) > MAX_PATH:
        raise InvalidRequestError(
            f"the path the node is told to read has more than {MAX_PATH} bytes; "
            "give a shorter one with --path"
        )
    tty = sys.stderr.isatty() and args.nodes.single
    shown: dict[int, tuple[Phase, int]] = {}

    def progress(p: UpdateProgress) -> None:
        tenth = 10 * p.sent // max(1, p.size)
        if shown.get(p.node_id) != (p.phase, tenth) or tty:
            end = "\r" if tty and p.phase is Phase.READING else "\n"
            print(
                f"node {p.node_id}: {p.phase.value}, {p.sent} of {counted(p.size, 'byte')}",
                end=end,
                file=sys.stderr,
                flush=True,
            )
        shown[p.node_id] = (p.phase, tenth)

    crc = image_crc(image)
    options = FirmwareOptions(
        args.start_timeout, args.read_timeout, args.restart_timeout, args.max_image_size
    )

    def make(node: int) -> Operation[tuple[bool, GetNodeInfoResponse]]:
        return operations.update_unless_current(
            client.protocol,
            node,
            image,
            path,
            force=args.force,
            progress=None if args.json else progress,
            options=options,
        )

    def data(node: int, outcome: tuple[bool, GetNodeInfoResponse]) -> dict[str, Any]:
        updated, info = outcome
        result = _info_dict(node, info)
        result.update(
            updated=updated, image=path, image_bytes=len(image), image_crc64we=f"{crc:#018x}"
        )
        return result

    def text(node: int, outcome: tuple[bool, GetNodeInfoResponse]) -> str:
        if not outcome[0]:
            return (
                f"node {node}: skipped, it runs {path} already (image CRC {crc:#018x}); "
                "--force updates anyway"
            )
        reported = data(node, outcome)["software_version"]["image_crc"]
        size = counted(len(image), "byte")
        return f"node {node}: updated with {path} ({size}, CRC-64-WE {crc:#018x}); " + (
            "the node reports the same CRC" if reported else "the node reports no image CRC"
        )

    return each(client, args, make, text, data)


# -- apply -------------------------------------------------------------------------------------


def _apply(client: BusClient, args: argparse.Namespace) -> int:
    text = _read_text(args.file)
    saved: list[paramfile.NodeParameters] | tuple[parmfile.ParmLine, ...]
    if parmfile.is_parm(args.file, text):
        saved = _named(args.file, parmfile.loads, text)
        if args.nodes.every or len(args.nodes.ids) != 1 or args.source is not None:
            raise InvalidRequestError(
                f"{args.file} is a .parm file (the DroneCAN GUI tool's): it names no node, "
                "so it is applied to one node named alone, without --from"
            )
    else:
        saved = _named(args.file, paramfile.loads, text)
    nodes = resolve(client, args.nodes)
    reads = client.run_all([operations.read_node(node) for node in nodes])
    failed = [(node, t.error) for node, t in zip(nodes, reads, strict=True) if t.error]
    if failed:
        for node, error in failed:
            _error(f"node {node}: {error_text(node, error)}")
        _error("nothing was set: every node must answer before any is changed")
        return exit_code(failed[0][1])
    plans: dict[int, list[paramfile.Change]] = {}
    for node, task in zip(nodes, reads, strict=True):
        current = task.result()
        entry = (
            parmfile.typed(saved, node, current.parameters)
            if isinstance(saved, tuple)
            else _entry_for(saved, current, args.source, alone=len(nodes) == 1)
        )
        plans[node] = paramfile.plan(node, entry, list(current.parameters))
        if not args.json:
            for change in plans[node]:
                print(f"node {node}: {change.name} {change.current} -> {plain(change.wanted)}")
            if entry.node_id != node:
                print(f"node {node}: the file's parameters of node {entry.node_id}")
    given = {
        node: change.wanted.value
        for node in nodes
        for change in plans[node]
        if change.name == indices.ESC_INDEX and isinstance(change.wanted, IntegerValue)
    }
    if given:
        _check_indices(args, given, client.run(indices.survey(client.protocol, nodes)))
    if args.dry_run:
        if args.json:
            _print_json({str(n): [_change(c) for c in plans[n]] for n in nodes})
        else:
            count = sum(map(len, plans.values()))
            print(f"dry run: {count} parameter{'s' * (count != 1)} would change; none set")
        return EXIT_OK
    applied: dict[int, list[str]] = {node: [] for node in nodes}
    tasks = client.run_all(
        [operations.apply_changes(node, plans[node], applied[node]) for node in nodes]
    )
    rows: list[dict[str, Any]] = []
    code = EXIT_OK
    for node, task in zip(nodes, tasks, strict=True):
        changes = plans[node]
        if task.error is None:
            line = (
                f"node {node}: {len(changes)} set, read back and saved"
                if changes
                else f"node {node}: as in the file, nothing set"
            )
            rows.append({"node_id": node, "ok": True, "set": [c.name for c in changes]})
        else:
            done = applied[node]
            code = code or exit_code(task.error)
            line = (
                f"node {node}: failed after setting {', '.join(done) or 'nothing'}: "
                f"{error_text(node, task.error)}; not saved"
            )
            rows.append({"node_id": node, "ok": False, "set": done, "error": str(task.error)})
        if not args.json:
            print(line)
    failed_ids = [row["node_id"] for row in rows if not row["ok"]]
    if args.json:
        _print_json({"nodes": rows, "total": len(rows), "failed": failed_ids})
    else:
        print(total(len(rows), failed_ids))
    if failed_ids:  # on standard error too, as every fleet action says it
        _error(total(len(rows), failed_ids))
    return code


_Loaded = TypeVar("_Loaded")
"""What a parameter file's text loads as."""


def _named(file: str, load: Callable[[str], _Loaded], text: str) -> _Loaded:
    """``load(text)``, a `paramfile.ParameterFileError` naming ``file``."""
    try:
        return load(text)
    except paramfile.ParameterFileError as error:
        raise paramfile.ParameterFileError(f"{file}: {error}") from None


def _read_text(file: str) -> str:
    try:
        with open(file, encoding="utf-8") as stream:
            return stream.read()
    except UnicodeDecodeError:
        raise paramfile.ParameterFileError(f"{file} is not a UTF-8 text file") from None


def _change(change: paramfile.Change) -> dict[str, Any]:
    return {"name": change.name, "current": change.current, "wanted": plain(change.wanted)}


def _entry_for(
    saved: list[paramfile.NodeParameters],
    node: paramfile.NodeParameters,
    source: int | None,
    alone: bool,
) -> paramfile.NodeParameters:
    """The file's parameters for ``node``: of ``source`` if given, else of the same unique id,
    else of the same node id, else the file's only node when ``node`` is the only one
    targeted (a replacement: one node's parameters onto several would give them all its
    ``esc_index``).

    Raises:
        ParameterFileError: None fits, or the file's node has another name.
    """
    entry = None
    if source is not None:
        entry = next((e for e in saved if e.node_id == source), None)
        if entry is None:
            raise paramfile.ParameterFileError(f"the file has no parameters of node {source}")
    else:
        entry = next((e for e in saved if e.unique_id == node.unique_id), None)
        if entry is None:
            entry = next((e for e in saved if e.node_id == node.node_id), None)
        if entry is None and len(saved) == 1 and alone:
            entry = saved[0]
    if entry is None:
        raise paramfile.ParameterFileError(
            f"the file has no parameters of node {node.node_id} (it has nodes "
            f"{', '.join(str(e.node_id) for e in saved)}); choose one with --from"
        )
    if entry.name and entry.name != node.name:
        raise paramfile.ParameterFileError(
            f"node {node.node_id} is {node.name!r}, the file's node {entry.node_id} is "
            f"{entry.name!r}: not applied"
        )
    return entry


# -- spin -----------------------------------------------------------------------------------------


def _allow_unknown(parser: argparse.ArgumentParser, what: str) -> None:
    parser.add_argument(
        "--allow-unknown-index",
        type=node_list,
        metavar="NODES",
        help=f"{what} although these nodes' esc_index cannot be read (nodes known to drive "
        "no motor: no answer, no such parameter, not a number); by default such a node "
        "refuses it",
    )


def _unknown_allowed(args: argparse.Namespace, survey: indices.IndexSurvey) -> list[int]:
    """The nodes ``--allow-unknown-index`` names (``all``: every node not read)."""
    given = args.allow_unknown_index
    if given is None:
        return []
    return list(survey.unread) if given.every else list(given.ids)


def _unknown_advice(error: EscIndexError) -> list[str]:
    """What to do about the nodes of ``error`` whose esc_index cannot be read: another
    ``--node-id`` for one that uses the tool's, the option that accepts them."""
    if not error.unread:
        return []
    ids = ",".join(map(str, error.unread))
    drive = "it drives" if len(error.unread) == 1 else "they drive"
    return [OWN_ID_ADVICE] * error.own + [f"add --allow-unknown-index {ids} if {drive} no motor"]


def _interrupt(signum: int, frame: object) -> None:
    raise KeyboardInterrupt


def _zeros(spin: Spin) -> str:
    indices_sent = ", ".join(str(i) for i in sorted(spin.setpoint))
    return f"zero throttle sent to esc_index {indices_sent} ({STOP_REPEATS} times)"


def _spin(client: BusClient, args: argparse.Namespace) -> int:
    if not args.yes:
        _error("esc spin moves motors: add --yes to confirm that they are free to turn")
        return EXIT_USAGE
    if any(given.every for given in args.nodes):
        raise InvalidRequestError("esc spin needs the nodes named: 'all' is refused")
    given = args.allow_unknown_index
    allow: AllowUnknown = () if given is None else "all" if given.every else given.ids
    started: list[Spin] = []

    def start(spin: Spin) -> None:
        started.append(spin)
        signal.signal(signal.SIGTERM, _interrupt)  # `kill` stops the motors too, like Ctrl-C

    try:
        result = client.spin(
            [n for given in args.nodes for n in given.ids],
            args.throttle,
            args.duration,
            rate=args.rate,
            watchdog=args.watchdog,
            silence=args.silence,
            max_temperature=args.max_temperature,
            max_current=args.max_current,
            allow_unknown=allow,
            on_start=start,
        )
    except SpinArgumentError as error:
        option = "--" + error.argument.replace("_", "-")
        raise InvalidRequestError(error.line(option)) from None
    except EscIndexError as error:
        raise InvalidRequestError(error.line(*_unknown_advice(error))) from None
    except SpinStoppedError as error:
        _error(f"{error.reason}; every motor stopped: {_zeros(started[0])}")
        return EXIT_FINDINGS if error.over_limit else EXIT_NO_ANSWER
    except KeyboardInterrupt:
        if not started:
            raise
        _error(f"interrupted; {_zeros(started[0])}")
        return EXIT_INTERRUPTED
    summary = [
        {
            "node_id": node.node_id,
            "esc_index": node.esc_index,
            "throttle": args.throttle,
            "peak_rpm": node.peak_rpm,
            "telemetry": node.telemetry,
        }
        for node in result.nodes
    ]
    if args.json:
        _print_json(summary)
    else:
        for row in summary:
            peak = "no telemetry" if row["peak_rpm"] is None else f"peak {row['peak_rpm']} rpm"
            print(
                f"node {row['node_id']} (esc_index {row['esc_index']}): throttle "
                f"{args.throttle:g} for {args.duration:g} s, {peak}; zero throttle sent"
            )
    _error(_zeros(started[0]))
    return EXIT_OK
