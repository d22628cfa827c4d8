"""Chebyshev's mobility and the Assur decomposition."""

from pathlib import Path

import pytest

from plans.errors import StructureError
from plans.model import from_dict, load
from plans.model.structure import DyadKind, analyse
from plans.model.variants import variant


def test_press_structure_matches_seed_000():
    st = analyse(load("samples/press.toml"))
    assert (st.n, st.p5, st.p4, st.W) == (5, 7, 0, 1)
    assert [(g.links, g.kind) for g in st.groups] == [((2, 3), DyadKind.RPR), ((4, 5), DyadKind.RRP)]
    assert st.formula() == "I(0,1) → II3(2,3) → II2(4,5)"
    assert st.chebyshev() == "W = 3n − 2p5 − p4 = 3·5 − 2·7 − 0 = 1"
    assert st.mechanism_class == 2


def test_fourbar_structure_matches_seed_001():
    st = analyse(load("samples/fourbar.toml"))
    assert (st.n, st.p5, st.W) == (3, 4, 1)
    assert [(g.links, g.kind) for g in st.groups] == [((2, 3), DyadKind.RRR)]


@pytest.mark.parametrize("n", range(10))
def test_variants_decompose(n):
    st = analyse(variant(n))
    kind = DyadKind.RRP if n % 2 == 0 else DyadKind.RRR
    assert st.W == 1 and [g.kind for g in st.groups] == [kind]


def _fourbar(**extra):
    data = {
        "frame": {"A": [0, 0], "D": [-0.2, 0]},
        "driver": {"angle_deg": 40, "omega": 10},
        "links": {
            "1": {"axis": ["A", "B"], "points": {"B": 0.05}},
            "2": {"axis": ["B", "C"], "points": {"C": 0.2}},
            "3": {"axis": ["D", "C"], "points": {"C": 0.15}},
        },
        "assembly": {"C": "above BD"},
    }
    data["links"].update(extra)
    return data


def test_locked_chain_reports_W():
    data = _fourbar()
    data["links"]["3"]["points"]["B"] = 0.1  # a fourth hinge makes a structure
    with pytest.raises(StructureError, match=r"3·3 − 2·5 − 0 = −1"):
        analyse(from_dict(data, "locked.toml"))


def test_class_three_group_is_named():
    # a four-bar plus a triad (ternary link 4 held by links 5, 6, 7): W = 3·7 − 2·10 = 1,
    # but no class-II group can be split off
    data = _fourbar()
    data["frame"].update({"H": [0.3, 0.0], "I": [0.3, 0.3]})
    data["links"]["4"] = {"axis": ["E", "F"], "points": {"F": 0.1, "G": [0.05, 0.05]}}
    data["links"]["5"] = {"axis": ["H", "E"], "points": {"E": 0.2}}
    data["links"]["6"] = {"axis": ["C", "F"], "points": {"F": 0.2}}
    data["links"]["7"] = {"axis": ["I", "G"], "points": {"G": 0.2}}
    with pytest.raises(StructureError, match=r"links 4, 5, 6, 7 do not form class-II groups"):
        analyse(from_dict(data, "triad.toml"))


def _with_guides(*guides: str):
    """A crank-slider whose rod carries further blocks (at C, D) on guides of the frame:
    only the guides' names matter here, not whether the chain moves."""
    body = """
[frame]
O = [0.0, 0.0]
[driver]
angle_deg = 30
omega = 10
[links.1]
axis = ["O", "A"]
points = { A = 0.1 }
[links.2]
axis = ["A", "B"]
points = { B = 0.4, C = 0.2, D = 0.3 }
"""
    for k, g in enumerate(guides):
        body += f"[links.{3 + k}]\npoints = {{ {'BCDE'[k]} = 0 }}\n"
        body += f"[[sliders]]\nlink = {3 + k}\nguide = {g}\n"
    import tomllib

    return from_dict(tomllib.loads(body), "guides.toml")


@pytest.mark.parametrize(("guides", "names"), [
    # the slider's guide is its axis x-x, inclined or not, y-y when vertical
    (["{ link = 0, through = [0, 0], angle_deg = 30 }"], ["x-x"]),
    (["{ link = 0, through = [0, 0], angle_deg = 90 }"], ["y-y"]),
    # an inclined guide beside a horizontal one takes the first free name
    (["{ link = 0, through = [0, 0], angle_deg = 0 }",
      "{ link = 0, through = [0, 0.1], angle_deg = 30 }"], ["x-x", "y-y"]),
    (["{ link = 0, through = [0, 0], angle_deg = 30 }",
      "{ link = 0, through = [0, 0], angle_deg = 90 }",
      "{ link = 0, through = [0, 0.1], angle_deg = 0 }"], ["z-z", "y-y", "x-x"]),
    # parallel guides may share a name: a plan's line only says "∥ x-x"
    (["{ link = 0, through = [0, 0], angle_deg = 30 }",
      "{ link = 0, through = [0, 0.1], angle_deg = 30 }"], ["x-x", "x-x"]),
    # the file's own label is kept, and counts as taken
    (['{ link = 0, through = [0, 0], angle_deg = 30, label = "n-n" }'], ["n-n"]),
    (['{ link = 0, through = [0, 0], angle_deg = 0, label = "x-x" }',
      "{ link = 0, through = [0, 0.1], angle_deg = 45 }"], ["x-x", "y-y"]),
])
def test_unlabelled_guides_are_named_by_notation_not_by_words(guides, names):
    """No default guide name is an English word, so a Russian note and sheet read right."""
    mech = _with_guides(*guides)
    assert [s.guide.label for s in mech.sliders] == names


@pytest.mark.parametrize(("name", "en", "ru"), [
    ('"Press"', "Press", "Press"),
    ('{ en = "Press", ru = "Пресс" }', "Press", "Пресс"),
    ('{ ru = "Пресс" }', "Пресс", "Пресс"),
])
def test_a_name_may_be_given_in_each_language(name, en, ru):
    import tomllib

    text = (Path(__file__).resolve().parent.parent / "samples" / "fourbar.toml").read_text("utf-8")
    text = text.replace('name = { en = "Four-bar linkage", ru = "Шарнирный четырёхзвенник" }',
                        f"name = {name}")
    mech = from_dict(tomllib.loads(text), "f.toml")
    assert (mech.name, mech.name_in("en"), mech.name_in("ru")) == (en, en, ru)


@pytest.mark.parametrize(("name", "message"), [
    ('{ de = "Presse" }', 'f.toml: name.de: unknown key — known: en, ru'),
    ("{ en = 5 }", "f.toml: name.en: must be a text of at most"),
    ("{}", 'f.toml: name: an empty table: give a text, or { en = "…", ru = "…" }'),
])
def test_a_bad_name_table_is_located(name, message):
    import tomllib

    from plans.errors import InputError

    text = (Path(__file__).resolve().parent.parent / "samples" / "fourbar.toml").read_text("utf-8")
    text = text.replace('name = { en = "Four-bar linkage", ru = "Шарнирный четырёхзвенник" }',
                        f"name = {name}")
    with pytest.raises(InputError) as err:
        from_dict(tomllib.loads(text), "f.toml")
    assert message in str(err.value)


def test_the_variants_are_named_in_the_language_of_the_note():
    assert variant(5).name_in("ru") == "Шарнирный четырёхзвенник, вариант 5"
    assert variant(5).name_in("en") == "Four-bar linkage, variant 5"
    assert variant(4).name_in("ru") == "Кривошипно-ползунный механизм, вариант 4"


def test_two_slots_of_one_link_in_two_directions_get_two_names():
    """yoke_on_rocker with link 2's guide on link 3 turned to 5°: both slots of link 3
    were 'x3-x3' in two directions; the second is now x3′-x3′."""
    import tomllib

    from plans.model.scenes import SCENES

    text = SCENES["yoke_on_rocker"].toml.replace("guide = { link = 3 }",
                                                  "guide = { link = 3, offset = 0.02, angle_deg = 5 }")
    mech = from_dict(tomllib.loads(text), "y.toml")
    labels = {s.link: s.guide.label for s in mech.sliders}
    assert (labels[2], labels[5]) == ("x3-x3", "x3′-x3′")


def test_an_unlabelled_slot_does_not_take_the_name_the_file_gave_another():
    import tomllib

    from plans.model.scenes import SCENES

    text = SCENES["yoke_on_rocker"].toml.replace(
        "guide = { link = 3 }", 'guide = { link = 3, offset = 0.02, angle_deg = 5, label = "x3-x3" }')
    labels = {s.link: s.guide.label for s in from_dict(tomllib.loads(text), "y.toml").sliders}
    assert (labels[2], labels[5]) == ("x3-x3", "x3′-x3′")
