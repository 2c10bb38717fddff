"""Render the built-in layouts as Markdown tables for the docs (called by the mkdocs hook)."""

from __future__ import annotations

from veronte4x.codec import layouts
from veronte4x.codec.compiler import FrameLayout, Placed
from veronte4x.codec.fields import ByteOrder, FieldKind
from veronte4x.codec.pwm import PwmPacking
from veronte4x.codec.routes import Route, RouteTable


def _position(layout: FrameLayout, p: Placed) -> tuple[str, str]:
    """Byte(s) and bit(s) of a field, bit 0 = least significant bit of its byte."""
    size = layout.fixed_size
    if layout.byte_order is ByteOrder.LITTLE:
        low, high = p.shift, p.shift + p.field.bits - 1
        first, last = low // 8, high // 8
    else:
        low, high = p.shift, p.shift + p.field.bits - 1
        first, last = size - 1 - high // 8, size - 1 - low // 8
    byte = str(first) if first == last else f"{first}-{last}"
    if first == last:
        lo, hi = low % 8, high % 8
        bits = str(lo) if lo == hi else f"{lo}-{hi}"
    elif low % 8 == 0 and (high + 1) % 8 == 0:
        bits = "all"
    else:
        bits = f"{low}-{high} of the {size}-byte {layout.byte_order.value}-endian word"
    return byte, bits


def _kind(layout: FrameLayout, p: Placed) -> str:
    f = p.field
    if f.kind is FieldKind.CONSTANT:
        return f"constant `{f.value:#04x}`"
    if f.kind is FieldKind.MAPPED:
        return "uint8, one of " + ", ".join(str(wire) for wire, _ in f.mapping)
    if f.kind is FieldKind.UNSIGNED:
        top = f.maximum if f.maximum is not None else (1 << f.bits) - 1
        return f"uint{f.bits}, 0..{top}"
    names = {FieldKind.BOOL: "bool", FieldKind.FLOAT32: "float32", FieldKind.SIGNED: f"int{f.bits}"}
    return names.get(f.kind, f.kind.name.lower())


def layout_table(layout: FrameLayout) -> str:
    """One layout as a Markdown table, with its source."""
    rows = ["| byte | bits | field | type | meaning |", "|---|---|---|---|---|"]
    for p in layout.placed:
        byte, bits = _position(layout, p)
        rows.append(
            f"| {byte} | {bits} | `{p.field.label}` | {_kind(layout, p)} | {p.field.description} |"
        )
    if layout.tail is not None:
        most = layout.tail.bits // 8
        first = layout.fixed_size
        rows.append(
            f"| {first}.. | all | `{layout.tail.label}` | 0..{most} bytes | "
            f"{layout.tail.description} |"
        )
    for attr, value in layout.implied:
        if value is not None:
            rows.append(f"| - | - | `{attr}` | fixed `{value}` | implied by the command byte |")
    size = (
        f"{layout.fixed_size} bytes"
        if layout.tail is None
        else f"{layout.fixed_size} to {layout.fixed_size + layout.tail.bits // 8} bytes"
    )
    title = layout.title or layout.name
    return f"### {title}\n\n{size}. Source: {layout.source}.\n\n" + "\n".join(rows) + "\n"


def protocol_tables() -> str:
    """Every built-in layout's table, in the order of the route table, both PWM packings."""
    tables = [RouteTable(packing) for packing in PwmPacking]
    found = dict.fromkeys(layout for table in tables for layout in table.layouts())
    opaque = {route.frame for route in tables[0].routes if tables[0].opaque(route)}
    return "\n".join(layout_table(layout) for layout in found if layout not in opaque)


def _class(route: Route, commands: list[int]) -> str:
    """A route's message class as the message-type table names it."""
    layout = route.frame
    first = layout.fields[0]
    if len(commands) > 1 and first.kind is FieldKind.MAPPED:
        return f"`{layout.name}({first.attr}={dict(first.mapping)[route.command]})`"
    return f"`{layout.name}`"


def _told(routes: list[Route]) -> str:
    """How the routes of one command are told apart."""
    told = []
    if any(r.sender is not None for r in routes):
        told.append("sender")
    if any(r.header is not None for r in routes):
        told.append("byte 1")
    if any(r.form for r in routes):
        told.append("length")
    return "by " + (told[0] if len(told) == 1 else ", ".join(told[:-1]) + " and " + told[-1])


def _payload(route: Route, table: RouteTable) -> str:
    if table.opaque(route):
        what = (route.frame.message.__doc__ or "").split(" (")[0]
        return f"{what}: raw, layout not public"
    return _bytes(route.frame)


def _bytes(layout: FrameLayout) -> str:
    size = layout.fixed_size
    if layout.tail is None:
        return f"{size} byte" + ("s" if size > 1 else "")
    return f"{size} to {size + layout.tail.bits // 8} bytes"


def command_table() -> str:
    """The message-type table: command byte to message class, from the route table."""
    table = RouteTable()
    commands = table.layout_commands()
    rows: list[tuple[int, str]] = []
    for command in table.commands():
        routes = table.of(command)
        if len(routes) == 1:
            route = routes[0]
            name = _class(route, commands[route.frame])
            rows.append((command, f"| {command} | {name} | {_payload(route, table)} |"))
        else:
            names = ", ".join(dict.fromkeys(f"`{r.frame.name}`" for r in routes))
            rows.append((command, f"| {command} | {names} | {_told(routes)} |"))
    for command in layouts.RESERVED_COMMANDS:
        rows.append((command, f"| {command} | reserved | `UnknownCommandError` |"))
    unrouted = set(range(256)) - set(table.commands()) - layouts.RESERVED_COMMANDS
    first = min(unrouted)
    assert unrouted == set(range(first, 256)), "unknown commands are the top ones"
    rows.append((first, f"| {first}-255 | unknown | `UnknownCommandError` |"))
    header = "| cmd | message class | payload |\n|---|---|---|\n"
    return header + "\n".join(row for _, row in sorted(rows)) + "\n"


def routing_table() -> str:
    """How the frames of the commands of several routes are told apart: by sender, byte 1
    and length."""
    table = RouteTable()
    rows = ["| cmd | sender | byte 1 | length | message |", "|---|---|---|---|---|"]
    for command in table.commands():
        routes = table.of(command)
        if len(routes) == 1:
            continue
        for route in routes:
            sender = f"`Sender.{route.sender.name}`" if route.sender is not None else "either"
            headed = any(r.header is not None for r in routes)
            header = (
                f"`0x{route.header:02X}`"
                if route.header is not None
                else ("any other" if headed else "any")
            )
            form = f"{_bytes(route.frame)}" + (f" ({route.form})" if route.form else "")
            rows.append(f"| {command} | {sender} | {header} | {form} | `{route.frame.name}` |")
    return "\n".join(rows) + "\n"
