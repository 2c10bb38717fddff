"""Render the built-in layouts as Markdown tables for the docs (called by the mkdocs hook)."""

from __future__ import annotations

from veronte4x.codec import layouts
from veronte4x.codec.compiler import FrameLayout, Placed
from veronte4x.codec.fields import ByteOrder, Kind
from veronte4x.codec.pwm import PWM_COMMANDS, PwmPacking


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
    if f.kind is Kind.CONSTANT:
        return f"constant `{f.value:#04x}`"
    if f.kind is Kind.MAPPED:
        return "uint8, one of " + ", ".join(str(wire) for wire, _ in f.mapping)
    if f.kind is Kind.UNSIGNED:
        top = f.maximum if f.maximum is not None else (1 << f.bits) - 1
        return f"uint{f.bits}, 0..{top}"
    names = {Kind.BOOL: "bool", Kind.FLOAT32: "float32", Kind.SIGNED: f"int{f.bits}"}
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
    """Every built-in layout's table, grouped as the protocol reference shows them."""
    groups = [
        *layouts.ARBITRATION_AND_VERSION,
        layouts.PWM_SET[PwmPacking.LSB_FIRST],
        layouts.PWM_SET[PwmPacking.MSB_FIRST],
    ]
    return "\n".join(layout_table(layout) for layout in groups)


def command_table() -> str:
    """The message-type table: command byte to message class."""
    rows = [
        (0, "| 0 | `Status`, `Score`, `Ready`, `ArbitrationVariable` | by sender and byte 1 |"),
        (1, "| 1 | `VersionRequest` (1 byte), `VersionResponse` (2+ bytes) | see below |"),
        (20, "| 20-255 | unknown | `UnknownCommandError` |"),
    ]
    for first, command in PWM_COMMANDS.items():
        rows.append((command, f"| {command} | `PwmSet(first_channel={first})` | 4 x 12 bits |"))
    for command, layout in layouts.OPAQUE.items():
        what = (layout.message.__doc__ or "").split(" (")[0]
        rows.append((command, f"| {command} | `{layout.name}` | {what}: raw, layout not public |"))
    for command in layouts.RESERVED_COMMANDS:
        rows.append((command, f"| {command} | reserved | `UnknownCommandError` |"))
    header = "| cmd | message class | payload |\n|---|---|---|\n"
    return header + "\n".join(row for _, row in sorted(rows)) + "\n"
