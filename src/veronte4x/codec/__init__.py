"""Encode and decode the Veronte 4x CAN messages (seed manual, chapter "CAN Bus protocol")."""

from __future__ import annotations

from veronte4x.codec.messages import (
    ArbitrationVariable,
    JetiBecTelemetry1,
    JetiBecTelemetry2,
    JetiEscTelemetry,
    JetiTemperature,
    MaintenanceCommand,
    McuCommand,
    McuTelemetry1,
    McuTelemetry2,
    Message,
    OpaqueMessage,
    PwmSet,
    Ready,
    Score,
    ScorpionEscTelemetry,
    Sender,
    Status,
    StickSelection,
    VersionRequest,
    VersionResponse,
)
from veronte4x.errors import DecodeError, EncodeError, UnknownCommandError, Veronte4xError

__all__ = [
    "ArbitrationVariable",
    "DecodeError",
    "EncodeError",
    "JetiBecTelemetry1",
    "JetiBecTelemetry2",
    "JetiEscTelemetry",
    "JetiTemperature",
    "MaintenanceCommand",
    "McuCommand",
    "McuTelemetry1",
    "McuTelemetry2",
    "Message",
    "OpaqueMessage",
    "PwmSet",
    "Ready",
    "Score",
    "ScorpionEscTelemetry",
    "Sender",
    "Status",
    "StickSelection",
    "UnknownCommandError",
    "Veronte4xError",
    "VersionRequest",
    "VersionResponse",
]
