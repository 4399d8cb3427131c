"""The shipped plants scan by scan from the command line (issue 21): ``ladderlab run --events`` feeds each
example the panel events a student would send, and every watched value is compared with a reference of
the plant's physics written here (REAL arithmetic in float32, as IEC REAL is). The seed's lab scenarios
(checklist 7.2 LAB-10, 7.3 LAB-20..26) run against the reference solutions with forced sensors."""

from __future__ import annotations

import json
import struct
from pathlib import Path

import pytest

from ladderlab.cli import main
from tests.support import EXAMPLES


def f32(x: float) -> float:
    return struct.unpack("f", struct.pack("f", x))[0]


def panel(scan: int, path: str, value: object) -> dict:
    return {"scan": scan, "kind": "panel", "path": path, "value": value}


def press(scan: int, path: str) -> list[dict]:
    """A click: TRUE before ``scan``, FALSE before the next."""
    return [panel(scan, path, True), panel(scan + 1, path, False)]


def force(scan: int, path: str, value: object) -> dict:
    return {"scan": scan, "kind": "force", "path": path, "value": value}


def run(capsys, tmp_path: Path, example: str, events: list[dict], scans: int, watch: list[str]) -> list[dict]:
    """Every scan's watched values (scan 0 first) of ``ladderlab run EXAMPLE --events``."""
    file = tmp_path / "events.jsonl"
    file.write_text("".join(json.dumps(e) + "\n" for e in events))
    args = ["run", str(EXAMPLES / example), "--events", str(file), "--cycles", str(scans), "--format", "jsonl"]
    code = main(args + [arg for path in watch for arg in ("--watch", path)])
    out, err = capsys.readouterr()
    assert code == 0, err
    rows = [json.loads(line) for line in out.splitlines()]
    assert [r["scan"] for r in rows] == list(range(scans))
    return rows


def column(rows: list[dict], *paths: str) -> list[tuple]:
    return [tuple(r[p] for p in paths) for r in rows]


# ---------------------------------------------------------------- room lighting (seed 003, 7.2)


def walker_reference(events: dict[int, tuple[str, bool]], scans: int) -> list[tuple[int, bool, bool, int]]:
    """(Pos, p1, p2, People) per scan: a walker needs 100 scans through the door; p1 sees 20..60, p2 40..80."""
    enter = leave = False
    was_enter = was_leave = False
    pos, direction, people, rows = 0, 0, 0, []
    for scan in range(scans):
        if scan in events:
            name, value = events[scan]
            enter, leave = (value, leave) if name == "Enter" else (enter, value)
        rising_enter, rising_leave = enter and not was_enter, leave and not was_leave
        was_enter, was_leave = enter, leave
        if direction == 0:
            if rising_enter:
                direction, pos = 1, 0
            elif rising_leave and people > 0:
                direction, pos = -1, 100
        if direction:
            pos += direction
            if pos >= 100 and direction > 0:
                people, direction = people + 1, 0
            elif pos <= 0 and direction < 0:
                people, direction = people - 1, 0
        walking = direction != 0
        rows.append((pos, walking and 20 <= pos <= 60, walking and 40 <= pos <= 80, people))
    return rows


def test_room_plant_walks_people_through_the_door(capsys, tmp_path):
    events = [*press(0, "Room.Enter"), *press(120, "Room.Enter"), *press(140, "Room.Leave"), *press(300, "Room.Leave")]
    rows = run(capsys, tmp_path, "room_lights", events, 420, ["Room.Pos", "p1", "p2", "Room.People", "lamp"])
    reference = walker_reference({e["scan"]: (e["path"].split(".")[1], e["value"]) for e in events}, 420)
    assert column(rows, "Room.Pos", "p1", "p2", "Room.People") == reference
    # the second press of Leave came while the walker was still in the door (140 < 220): it was ignored
    assert rows[-1]["Room.People"] == 1 and rows[-1]["lamp"] is True


def test_lab_10_one_person_enters_and_leaves(capsys, tmp_path):
    """Checklist 7.2, LAB-10: the spec's table, the sensors forced (the plant's own values do not count)."""
    table = [(0, 0), (1, 0), (1, 1), (0, 1), (0, 0), (0, 1), (1, 1), (1, 0), (0, 0)]
    events = [force(scan, path, bool(v)) for scan, row in enumerate(table) for path, v in zip(("p1", "p2"), row)]
    rows = run(capsys, tmp_path, "room_lights", events, 9, ["Lights.VX", "Lights.VIX", "lamp"])
    assert column(rows, "Lights.VX", "Lights.VIX", "lamp") == [
        (0, 0, False),
        (0, 0, False),
        (1, 0, True),
        (1, 0, True),
        (1, 0, True),
        (1, 0, True),
        (1, 1, False),
        (1, 1, False),
        (1, 1, False),
    ]


# ---------------------------------------------------------------- fire alarm (seed 003, 7.3; the plant in LD)


def test_smoke_plant_sensors_follow_the_fire_after_their_delays(capsys, tmp_path):
    """The fire from scan 0 (time 10 ms): each sensor's TON sees it from then; its Q at time 10 + PT."""
    events = [panel(0, "Smoke.Fire1", True), panel(600, "Smoke.Fire1", False), *press(700, "off2")]
    rows = run(capsys, tmp_path, "fire_alarm", events, 720, ["d11", "d12", "d13", "lamp1", "alarm"])
    on_from = {"d11": (10 + 500) // 10 - 1, "d12": (10 + 1500) // 10 - 1, "d13": (10 + 4000) // 10 - 1}
    for path, first in on_from.items():
        assert [r[path] for r in rows] == [first <= s < 600 for s in range(720)], path
    # the vote (d11 and d12) from scan 150 (time 1510) confirmed 2 s later; the siren holds until off
    assert [r["alarm"] for r in rows] == [349 < s < 700 for s in range(720)]
    assert [r["lamp1"] for r in rows] == [49 < s < 600 for s in range(720)]


def test_burnt_toast_lights_the_lamp_and_never_the_siren(capsys, tmp_path):
    events = [panel(0, "Smoke.Toast2", True), panel(400, "Smoke.Toast2", False)]
    rows = run(capsys, tmp_path, "fire_alarm", events, 450, ["d22", "lamp2", "alarm"])
    assert column(rows, "d22", "lamp2") == [(s < 400, s < 400) for s in range(450)]
    assert not any(r["alarm"] for r in rows)


@pytest.mark.parametrize(
    ("sensors", "alarm"),
    [
        (("d11", "d21"), False),  # LAB-23: one sensor per room is no vote
        (("d11", "d13"), True),  # LAB-22: every pair of a room votes
        (("d12", "d13"), True),
        (("d21", "d22"), True),
        (("d22", "d23"), True),
    ],
)
def test_lab_22_23_two_of_three_per_room_with_the_2_s_confirmation(capsys, tmp_path, sensors, alarm):
    events = [force(0, path, True) for path in sensors]
    rows = run(capsys, tmp_path, "fire_alarm", events, 260, ["alarm", "lamp1", "lamp2"])
    # forced from scan 0 (time 10): confirmed at time 2010, scan 200
    assert [r["alarm"] for r in rows] == [alarm and s >= 200 for s in range(260)]
    assert rows[0]["lamp1"] == any(p.startswith("d1") for p in sensors)


def test_lab_24_25_manual_on_and_off_wins_while_held(capsys, tmp_path):
    events = [*press(0, "on2"), *press(10, "off1"), force(20, "d21", True), force(20, "d22", True)]
    events += [panel(300, "off2", True), panel(305, "off2", False)]
    rows = run(capsys, tmp_path, "fire_alarm", events, 320, ["alarm"])
    # forced at scan 20 (time 210): confirmed at time 2210, scan 220; off held for scans 300..304 wins
    expected = [s < 10 or 220 <= s < 300 or s >= 305 for s in range(320)]
    assert [r["alarm"] for r in rows] == expected


# ---------------------------------------------------------------- traffic lights


def test_the_street_lets_the_pedestrian_cross_on_green_in_3_s(capsys, tmp_path):
    """A request at scan 0: 5 s green (scan 500), 2 s yellow, 1 s all red: walk from scan 804 (each step's
    timer restarts one scan after the step changes). The plant sees walk in the next scan and needs 300 scans."""
    events = press(0, "Street.Arrive")
    rows = run(capsys, tmp_path, "traffic_lights", events, 1800, ["Crossing.Step", "WalkGreen", "Street.WalkerPos"])
    steps = [r["Crossing.Step"] for r in rows]
    assert [steps.index(k) for k in range(1, 6)] == [500, 702, 804, 1306, 1608] and steps[1710] == 0
    crossing = [r["Street.WalkerPos"] for r in rows]
    assert crossing[804] == 0 and crossing[805:1104] == list(range(1, 300)) and crossing[1104:] == [300] * 696
    more = run(capsys, tmp_path, "traffic_lights", events, 1800, ["Street.Crossed", "Street.Accidents"])
    assert [r["Street.Crossed"] for r in more] == [int(s >= 1104) for s in range(1800)]
    assert {r["Street.Accidents"] for r in more} == {0}


# ---------------------------------------------------------------- tank filling (the plant in FBD)


def test_the_tank_fills_and_drains_in_real_arithmetic(capsys, tmp_path):
    events = [panel(0, "Auto", True), panel(3000, "Tank.Demand", 4.0)]
    rows = run(capsys, tmp_path, "tank_filling", events, 5000, ["Tank.Level", "Pump", "LSL", "LSH"])
    level, pump, demand, expected = 0.0, False, 1.5, []
    auto = True
    for scan in range(5000):
        if scan == 3000:
            demand = 4.0
        added = f32(level + (f32(0.05) if pump else 0.0))
        level = min(max(f32(added - f32(f32(demand) * f32(0.01))), 0.0), 100.0)
        low, high = level <= 20.0, level >= 80.0
        pump = auto and (low or pump) and not high  # the LD reference solution, the plant's input next scan
        expected.append((level, pump, low, high))
    assert column(rows, "Tank.Level", "Pump", "LSL", "LSH") == expected


# ---------------------------------------------------------------- conveyor with a sorter


def test_the_belt_carries_a_box_past_the_sensors(capsys, tmp_path):
    """Start at scan 0 (the belt runs from then; the plant moves boxes from scan 1), a tall box put on at scan 2."""
    events = [*press(0, "Start"), *press(2, "Line.AddTall")]
    rows = run(capsys, tmp_path, "conveyor_sorter", events, 200, ["Line.Pos[1]", "AtCheck", "Tall", "AtPusher"])
    pos, expected = 0.0, []
    for scan in range(200):
        if scan >= 2:  # put on and moved in the same scan of the plant
            pos = f32(pos + f32(0.4))
        seen = scan >= 2 and 28.0 <= pos <= 34.0
        expected.append((pos if scan >= 2 else 0.0, seen, seen, scan >= 2 and 67.0 <= pos <= 73.0))
    # up to the pusher's eye; there the program stops the belt in the same scan (it runs after the plant): the
    # box stays where the eye saw it while the pusher sweeps it off
    at_pusher = next(scan for scan, row in enumerate(expected) if row[3])
    assert column(rows, "Line.Pos[1]", "AtCheck", "Tall", "AtPusher")[: at_pusher + 1] == expected[: at_pusher + 1]
    assert {r["Line.Pos[1]"] for r in rows[at_pusher:]} == {expected[at_pusher][0]}


def test_the_sorter_pushes_tall_boxes_off(capsys, tmp_path):
    events = [*press(0, "Start"), *press(2, "Line.AddTall"), *press(40, "Line.AddSmall"), *press(80, "Line.AddTall")]
    rows = run(capsys, tmp_path, "conveyor_sorter", events, 800, ["Line.Passed", "Line.Rejected", "Line.Wrong"])
    assert column(rows, "Line.Passed", "Line.Rejected", "Line.Wrong")[-1] == (1, 2, 0)


# ---------------------------------------------------------------- garage door


def test_the_door_travels_a_quarter_per_scan_between_the_limits(capsys, tmp_path):
    events = [*press(0, "Button"), *press(500, "Button"), panel(600, "Door.Car", True)]
    rows = run(capsys, tmp_path, "garage_door", events, 700, ["Door.Pos", "Top", "Bottom", "Obstacle", "Door.Hits"])
    positions = [r["Door.Pos"] for r in rows]
    assert positions[:401] == [0.25 * s for s in range(401)]  # up from scan 1, at the top at scan 400
    assert positions[400:501] == [100.0] * 101
    assert positions[501:601] == [100.0 - 0.25 * (s - 500) for s in range(501, 601)]  # closing from scan 501
    # the car at scan 600: the plant's photo eye sees it in that scan, the program reverses in the same scan
    # (it runs after the plant), the door goes up from scan 601
    assert positions[600] == 75.0 and positions[601:604] == [75.25, 75.5, 75.75]
    assert [r["Top"] for r in rows][:401] == [s == 400 for s in range(401)] and rows[0]["Bottom"] is True
    assert {r["Door.Hits"] for r in rows} == {0}


# ---------------------------------------------------------------- star-delta start (EX-03)


def test_the_motor_runs_up_in_star_then_in_delta_without_a_trip(capsys, tmp_path):
    rows = run(
        capsys,
        tmp_path,
        "star_delta",
        press(0, "sb1"),
        2000,
        ["km1", "km2", "Motors.Speed[1]", "Motors.Current[1]", "Motors.Tripped[1]"],
    )
    assert [(r["km1"], r["km2"]) for r in rows] == [(s < 1200, s >= 1200) for s in range(2000)]  # EX-03: 12 s
    speed, expected = 0.0, []
    for scan in range(2000):
        wye, delta = scan >= 1 and scan - 1 < 1200, scan - 1 >= 1200  # the plant sees the contactors a scan later
        if wye:
            speed = f32(speed + f32(f32(f32(58.0) - speed) * f32(0.005)))
            current = f32(f32(2.0) + f32(f32(f32(58.0) - speed) * f32(0.08)))
        elif delta:
            speed = f32(speed + f32(f32(f32(100.0) - speed) * f32(0.005)))
            current = f32(f32(6.0) + f32(f32(f32(100.0) - speed) * f32(0.15)))
        else:
            speed, current = f32(speed * f32(0.995)), 0.0
        expected.append((speed, current, False))
    assert column(rows, "Motors.Speed[1]", "Motors.Current[1]", "Motors.Tripped[1]") == expected


def test_a_direct_delta_start_or_a_stuck_delta_contactor_trips_the_motor(capsys, tmp_path):
    events = [{"scan": 0, "kind": "fault", "path": "km2", "mode": "stuck_true"}, *press(0, "sb1")]
    rows = run(capsys, tmp_path, "star_delta", events, 5, ["Motors.Tripped[1]", "Motors.Speed[1]"])
    assert [r["Motors.Tripped[1]"] for r in rows] == [True] * 5  # star and delta at once from the first scan


# ---------------------------------------------------------------- batch mixer


def test_a_batch_is_made_as_the_recipe_says_and_the_emergency_stop_ends_the_next(capsys, tmp_path):
    events = [*press(0, "StartBatch"), *press(3500, "StartBatch"), panel(3700, "EStop", False)]
    rows = run(capsys, tmp_path, "batch_mixer", events, 3800, ["Batch.Step", "Level", "ValveA", "Vessel.Good", "Done"])
    level, first = 0.0, []
    while level < 40.0:  # fill A from scan 1 (the plant sees ValveA a scan after the program opens it)
        level = f32(level + f32(0.1))
        first.append(level)
    a_done = len(first)  # the scan in which the level reaches 40 %: the program moves on to B
    assert [r["Level"] for r in rows[1 : a_done + 1]] == first
    steps = [r["Batch.Step"] for r in rows]
    assert steps[a_done] == 2 and steps[a_done - 1] == 1
    assert rows[3499]["Vessel.Good"] == 1 and rows[3499]["Done"] is True and steps[3499] == 0
    assert rows[3600]["ValveA"] is True and rows[3700]["ValveA"] is False and steps[3700] == 0
