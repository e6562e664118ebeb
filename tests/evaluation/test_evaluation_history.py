from __future__ import annotations

from evaluation_helpers import launch, linted, node

from launch_linter.evaluation.history import (
    FIXED,
    GONE,
    PERSISTING,
    follow_history,
    match_transform,
    render_history,
)
from launch_linter.model.beliefs import BeliefSet
from launch_linter.model.diagnostic import Belief

RULES = ["self_transform", "rot_degrees", "reversed_name", "parse_error", "name_null_rot"]


def test_fixed_persisting_and_gone() -> None:
    earlier = linted(
        launch(
            node("self_tf", "0 0 0 0 0 0 base_link base_link 100"),
            node("laser_tf", "0.1 0 0.2 90 0 0 base_link laser 100"),
            node("cam_tf", "0 0 0.3 180 0 0 base_link camera 100"),
        ),
        latest=False, version="c0",
    )
    latest = linted(
        launch(
            node("self_tf", "0 0 0 0 0 0 base_link base_link 100"),
            node("laser_tf", "0.1 0 0.2 1.5708 0 0 base_link laser 100"),
        )
    )
    history = follow_history([earlier, latest], RULES)
    assert history.rules["self_transform"].outcomes == {FIXED: 0, PERSISTING: 1, GONE: 0}
    # laser_tf now in radians (fixed); cam_tf was removed (gone)
    assert history.rules["rot_degrees"].outcomes == {FIXED: 1, PERSISTING: 0, GONE: 1}
    assert history.rules["rot_degrees"].immature[FIXED] == 1
    assert history.earlier_versions == 1 and history.files_with_history == 1
    fixed = next(f for f in history.faults if f.outcome == FIXED)
    assert fixed.transform_after is not None and fixed.transform_after.name == "laser_tf"
    assert fixed.after is None


def test_a_fault_in_several_earlier_versions_counts_once() -> None:
    bad = node("laser_tf", "0 0 0 90 0 0 base_link laser 100")
    versions = [
        linted(launch(bad), latest=False, version="c0"),
        linted(launch(bad, node("x", "0 0 0 0 0 0 a b 1")), latest=False, version="c1"),
        linted(launch(node("laser_tf", "0 0 0 1.57 0 0 base_link laser 100"))),
    ]
    counts = follow_history(versions, RULES).rules["rot_degrees"]
    assert counts.diagnostics == 2
    assert counts.outcomes[FIXED] == 1 and counts.faults == 1


def test_transforms_are_matched_by_name_then_signature() -> None:
    # reversed_name fixed by renaming the node: the signature finds the transform again
    earlier = linted(launch(node("map_to_odom", "0 0 0 0 0 0 odom map 100")), latest=False)
    latest = linted(launch(node("odom_to_map", "0 0 0 0 0 0 odom map 100")))
    counts = follow_history([earlier, latest], RULES).rules["reversed_name"]
    assert counts.outcomes == {FIXED: 1, PERSISTING: 0, GONE: 0}
    # ... and fixed by swapping the frames: the name finds it
    latest = linted(launch(node("map_to_odom", "0 0 0 0 0 0 map odom 100")))
    assert follow_history([earlier, latest], RULES).rules["reversed_name"].outcomes[FIXED] == 1
    old, new = earlier.transforms[0], latest.transforms[0]
    assert match_transform(old, (new,)) is new
    other = linted(launch(node("tf_a", "0 0 0 0 0 0 x y 100"))).transforms
    assert match_transform(old, other) is None


def test_a_renamed_file_is_compared_with_its_head_file() -> None:
    bad = node("laser_tf", "0 0 0 90 0 0 base_link laser 100")
    good = node("laser_tf", "0 0 0 1.57 0 0 base_link laser 100")
    versions = [
        linted(launch(bad), path="old/a.launch", latest=False, head_paths=("new/a.launch",)),
        linted(launch(good), path="new/a.launch"),
        linted(launch(bad), path="other.launch", latest=False, repo="r/orphan"),
    ]
    history = follow_history(versions, RULES)
    assert history.rules["rot_degrees"].outcomes[FIXED] == 1
    assert history.orphans == 1
    assert history.faults[0].latest.path == "new/a.launch"


def test_file_level_diagnostics_compare_messages() -> None:
    broken = linted("<launch>\n  <node pkg='tf'\n</launch>\n", latest=False)
    fixed = linted(launch(node("a", "0 0 0 0 0 0 x y 100")))
    assert follow_history([broken, fixed], RULES).rules["parse_error"].outcomes[FIXED] == 1
    still = linted("<launch>\n  <node pkg='tf'\n</launch>\n")
    assert follow_history([broken, still], RULES).rules["parse_error"].outcomes[PERSISTING] == 1


def test_belief_faults_persist_only_for_the_same_belief() -> None:
    beliefs = BeliefSet("test", 1.0, (Belief("name_null_rot", "map_to_odom", None, 10, 10, 3.0),))
    rotated = node("map_to_odom", "0 0 0 0.5 0 0 map odom 100")
    earlier = linted(launch(rotated), latest=False, beliefs=beliefs)
    assert [d.rule for d in earlier.diagnostics] == ["name_null_rot"]
    same = linted(launch(rotated), beliefs=beliefs)
    zero = linted(launch(node("map_to_odom", "0 0 0 0 0 0 map odom 100")), beliefs=beliefs)
    assert follow_history([earlier, same], RULES).rules["name_null_rot"].outcomes[PERSISTING] == 1
    assert follow_history([earlier, zero], RULES).rules["name_null_rot"].outcomes[FIXED] == 1


def test_render_lists_every_rule_and_examples() -> None:
    earlier = linted(launch(node("laser_tf", "0 0 0 90 0 0 base_link laser 100")), latest=False)
    latest = linted(launch(node("laser_tf", "0 0 0 1.57 0 0 base_link laser 100")))
    text = render_history(follow_history([earlier, latest], RULES), ["- preamble"])
    for rule in RULES:
        assert f"| {rule} |" in text
    assert "| rot_degrees | 1 | 1 | 1 | 0 | 0 | 100% | 1 | 1 | 0 |" in text
    assert "### `rot_degrees`" in text and "**fixed** — r/one: `launch/a.launch`" in text
    assert "`0 0 0 1.57 0 0 base_link laser 100`" in text
