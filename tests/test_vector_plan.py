"""The plan view draws any polygon of vectors from a pole with recorded sources
(drawing.views.plans): a force plan needs no second renderer."""

from __future__ import annotations

from types import SimpleNamespace as NS

import pytest

from drawing.scene import Arrow, Group, Segment, Text, flatten
from drawing.styles import LineType
from drawing.views import vector_plan_view


def _force_plan():
    """G₂ and F laid end to end from the pole, closed by R₁₂ (⊥ AB through c) and R₃₄
    (∥ the guide, through the pole): the two unknown forces where the two lines cross."""
    crossing = NS(kind="intersection", equation="R12 + G2 + F + R34 = 0",
                  lines=(NS(through="c", direction=1j), NS(through="p", direction=1 + 0j)))
    points = {
        "b": NS(name="b", value=0 - 400j, source=NS(kind="component", equation="", lines=())),
        "c": NS(name="c", value=600 - 400j, source=NS(kind="component", equation="", lines=())),
        "d": NS(name="d", value=600 + 0j, source=crossing),
    }
    vectors = (NS(start="p", end="b", component="gravity", label="G_2"),
               NS(start="b", end="c", component="applied", label="F"),
               NS(start="c", end="d", component="reaction", label="R_12"),
               NS(start="d", end="p", component="reaction", label="R_34"))
    return NS(pole="p", points=points, vectors=vectors, mu=20.0, unit="N")


def test_a_force_plan_is_drawn_by_the_plan_view():
    plan = _force_plan()
    view = vector_plan_view(plan, "force-1", "План сил, μ_F = 20 Н/мм", "f", "1")
    items = flatten(view.items)
    arrows = [g for g in view.items if isinstance(g, Group) and g.name.startswith("vec ")]
    assert sorted(g.name for g in arrows) == ["vec f-bc-1", "vec f-cd-1", "vec f-dp-1",
                                              "vec f-pb-1"]
    lengths = {g.name: next(it for it in g.items if isinstance(it, Arrow)).length for g in arrows}
    assert lengths["vec f-pb-1"] == pytest.approx(20.0)  # 400 N at 20 N/mm
    assert lengths["vec f-bc-1"] == pytest.approx(30.0)
    thin = [it for it in items if isinstance(it, Segment) and it.line is LineType.THIN]
    assert len(thin) == 2  # the two lines that close the polygon
    texts = {it.text for it in items if isinstance(it, Text)}
    assert {"p", "b", "c", "d"} <= texts
    assert "R12 + G2 + F + R34 = 0" in texts  # the equation under the plan
    assert view.caption == "План сил, μ_F = 20 Н/мм"
