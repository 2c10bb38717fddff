"""Every built-in layout cites where it comes from as a user can look it up."""

from __future__ import annotations

import pytest

from veronte4x.codec import layouts
from veronte4x.codec.compiler import FrameLayout
from veronte4x.codec.pwm import PwmPacking

BUILT_IN = [
    *layouts.ARBITRATION_AND_VERSION,
    *(layouts.PWM_SET[packing] for packing in PwmPacking),
    *layouts.OPAQUE.values(),
]


@pytest.mark.parametrize("layout", BUILT_IN, ids=lambda layout: layout.title or layout.name)
def test_sources_name_the_manual_or_embention_never_internal_files(layout: FrameLayout) -> None:
    assert layout.source.startswith(("Veronte Autopilot 4x Software Manual", "Embention's"))
    for internal in ("seed", "notes", ".md"):
        assert internal not in layout.source
