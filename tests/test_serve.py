"""tarsim serve's routes answer as the command line does: the same numbers, results.json,
figures, steps and one-line errors, asked through starlette's test client."""

from __future__ import annotations

import json
import warnings
from pathlib import Path

import pytest
from click.testing import CliRunner

pytest.importorskip("starlette")
pytest.importorskip("httpx")

with warnings.catch_warnings():       # starlette would rather have httpx2; httpx serves
    warnings.simplefilter("ignore")
    from starlette.testclient import TestClient  # noqa: E402

from tarsim.exercises.catalog import everything  # noqa: E402
from tarsim.exercises.cli import cli  # noqa: E402
from tarsim.exercises.serve import make_app  # noqa: E402

FOUR_BAR = everything()["four-bar"].read_text(encoding="utf-8")


@pytest.fixture(scope="module")
def folder(tmp_path_factory) -> Path:
    root = tmp_path_factory.mktemp("served")
    (root / "fb.toml").write_text(FOUR_BAR, encoding="utf-8")
    (root / "sub").mkdir()
    (root / "sub" / "other.toml").write_text(FOUR_BAR, encoding="utf-8")
    (root / ".hidden").mkdir()
    (root / ".hidden" / "secret.toml").write_text(FOUR_BAR, encoding="utf-8")
    (root / "notes.txt").write_text("not an exercise", encoding="utf-8")
    return root


@pytest.fixture(scope="module")
def client(folder):
    with TestClient(make_app(folder)) as c:
        yield c


def _cli_solve(tmp: Path, source: str, *args: str) -> Path:
    """``tarsim solve`` of ``source`` into a folder; the folder."""
    out = tmp / f"{Path(source).stem}-{len(list(tmp.iterdir()))}"
    r = CliRunner().invoke(cli, ["solve", source, "-o", str(out), "--no-pdf", *args],
                           prog_name="tarsim")
    assert r.exit_code == 0, r.output
    return out


def test_exercises_lists_the_bundled_ones_and_the_folders_files(client):
    got = client.get("/api/exercises").json()
    by_id = {e["id"]: e for e in got["bundled"]}
    assert by_id["four-bar"] == {"id": "four-bar", "title": "Four-bar crank-rocker",
                                 "chapter": "linkages"}
    assert by_id["planetary-q1"]["chapter"] == "gears"
    assert len(by_id) == len(everything())
    # .toml files only, relative to the folder, hidden folders passed by
    assert got["files"] == ["fb.toml", "sub/other.toml"]


def test_exercise_gives_a_bundled_files_text_and_a_folders(client):
    assert client.get("/api/exercise", params={"id": "four-bar"}).json() == \
        {"id": "four-bar", "toml": FOUR_BAR}
    assert client.get("/api/exercise", params={"file": "sub/other.toml"}).json() == \
        {"file": "sub/other.toml", "toml": FOUR_BAR}
    r = client.get("/api/exercise", params={"id": "four-barr"})
    assert r.status_code == 404 and "did you mean 'four-bar'?" in r.json()["error"]
    assert client.get("/api/exercise", params={"file": "nothing.toml"}).status_code == 404


def test_solve_gives_the_four_bars_numbers_and_solves_results(client, tmp_path):
    r = client.post("/api/solve", json={"toml": FOUR_BAR, "lang": "en", "id": "four-bar"})
    assert r.status_code == 200
    got = r.json()
    # The exercise's numbers as the notes give them, to their 4 figures (±half a unit in
    # the last); the analytic solver's, in rad/s and the file's mm/s.
    assert got["title"] == "Four-bar crank-rocker" and got["angle"] == 60.0
    assert got["omega"]["2"] == 10.0
    assert got["omega"]["3"] == pytest.approx(-2.578, abs=5e-4)
    assert got["omega"]["4"] == pytest.approx(2.916, abs=5e-4)
    assert set(got["omega"]) == set(got["alpha"]) == {"2", "3", "4"}
    vb = got["velocities"]["B"]
    assert vb["unit"] == "mm/s" and vb["magnitude"] == pytest.approx(583.2, abs=0.05)
    assert vb["angle_deg"] == pytest.approx(-172.4, abs=0.05)
    assert got["velocities"]["A"]["magnitude"] == pytest.approx(1000.0, rel=1e-12)  # ω2·O2A
    assert "O2" not in got["velocities"]           # a frame pivot does not move
    assert got["accelerations"]["A"]["unit"] == "mm/s²"
    # where the points stand, in the file's mm and axes: A at 100 mm and 60°, I23's place
    assert got["points"]["O4"] == [300.0, 0.0]
    assert got["points"]["A"] == pytest.approx([50.0, 86.60254], abs=1e-5)
    assert got["points"]["B"] == pytest.approx([273.679, 198.261], abs=5e-4)   # I34's
    # The record is results.json as tarsim solve writes it, number for number.
    out = _cli_solve(tmp_path, "four-bar")
    assert got["results"] == json.loads((out / "results.json").read_text(encoding="utf-8"))
    # The figures are solve's, in its order, each SVG as it writes it.
    names = [f["name"] for f in got["figures"]]
    assert names == ["centres", "circle-diagram", "V_B-radius-rotation",
                     "V_B-parallel-line", "V_B-components"]
    for f in got["figures"]:
        assert f["svg"] == (out / f"{f['name']}.svg").read_text(encoding="utf-8")
    # The steps are steps.md's, each numbered step an item of its list.
    steps_md = (out / "steps.md").read_text(encoding="utf-8")
    numbered = [line for line in steps_md.splitlines() if line[:1].isdigit()]
    assert got["steps"].count("<li value=") == len(numbered)
    assert "<h2>Instant centres (<code>centres.svg</code>)</h2>" in got["steps"]


def test_the_table_is_steps_mds_results_with_their_numbers(client):
    table = client.post("/api/solve", json={"toml": FOUR_BAR, "figures": False}).json()["table"]
    rows = {row["quantity"]: row for row in table}
    assert [r["quantity"] for r in table][-3:] == ["V_B", "V_B (parallel-line)",
                                                   "V_B (components)"]
    vb = rows["V_B"]
    assert vb["construction"] == vb["analytic"] == "583.192 mm/s at −172.4°"
    assert vb["value"] == pytest.approx(583.1916, abs=1e-4) and vb["unit"] == "mm/s"
    # drawn and solved agree to rounding: the check's tolerance is 1e-9 here
    assert vb["error"] < 1e-12 and vb["passed"] and vb["method"] == "radius rotation"
    w3 = rows["omega3"]
    assert w3["construction"] == "−2.57846 rad/s (cw)" and w3["unit"] == "rad/s"
    assert w3["method"] == "instant centres (ω ratio)"
    assert rows["I13"]["construction"] == "(243.914, 422.471) mm" and rows["I13"]["unit"] is None


def test_without_figures_the_numbers_are_the_same(client):
    full = client.post("/api/solve", json={"toml": FOUR_BAR}).json()
    quick = client.post("/api/solve", json={"toml": FOUR_BAR, "figures": False}).json()
    assert quick["figures"] == [] and quick["steps"] is None
    for key in ("omega", "alpha", "velocities", "accelerations", "results", "table"):
        assert quick[key] == full[key]


def test_an_angle_solves_as_solve_angle_does(client, tmp_path):
    got = client.post("/api/solve", json={"toml": FOUR_BAR, "angle": 120, "id": "four-bar",
                                          "figures": False}).json()
    out = _cli_solve(tmp_path, "four-bar", "--angle", "120")
    assert got["angle"] == 120.0
    assert got["results"] == json.loads((out / "results.json").read_text(encoding="utf-8"))
    assert got["omega"]["3"] == pytest.approx(
        got["results"]["positions"][0]["quantities"]["omega3"]["reference"]["value"], rel=1e-12)


def test_persian_says_the_title_steps_and_table_in_persian(client):
    got = client.post("/api/solve", json={"toml": FOUR_BAR, "lang": "fa"}).json()
    assert got["title"] == "چهار میله‌ای لنگ - آونگ" and got["lang"] == "fa"
    assert "مراکز آنی" in got["steps"]
    assert {row["quantity"]: row for row in got["table"]}["omega3"]["construction"] == \
        "−۲٫۵۷۸۴۶ rad/s (ساعتگرد)"
    assert got["figures"][0]["title"] == "مراکز آنی"


def test_a_link_too_short_is_the_clis_line_with_the_link(client, tmp_path, monkeypatch):
    short = FOUR_BAR.replace("AB = 250", "AB = 50")
    r = client.post("/api/solve", json={"toml": short, "file": "short.toml"})
    assert r.status_code == 422
    got = r.json()
    monkeypatch.chdir(tmp_path)
    Path("short.toml").write_text(short, encoding="utf-8")
    cli_run = CliRunner().invoke(cli, ["solve", "short.toml", "--no-pdf"], prog_name="tarsim")
    assert cli_run.exit_code == 1
    assert got["error"] == cli_run.output.strip().removeprefix("Error: ")
    assert got["error"].startswith("short.toml:19: link 3 (coupler, AB = 50 mm) cannot reach")
    # line 19 is link 3's [[link]] table: where the page shows the error
    assert got["where"] == {"link": 3, "joint": "B", "line": 19}
    # unsaved, the text is named as the page's exercise
    unsaved = client.post("/api/solve", json={"toml": short}).json()
    assert unsaved["error"].startswith("exercise.toml:19: link 3")
    # and the server goes on answering
    assert client.post("/api/solve", json={"toml": FOUR_BAR, "figures": False}).status_code == 200


def test_bad_input_names_its_field_and_mobility(client):
    bad = client.post("/api/solve", json={"toml": FOUR_BAR.replace("AB = 250", "AB = -50")})
    assert bad.status_code == 422
    assert bad.json() == {"error": "exercise.toml:23: [link 3, AB] length AB of link 3 must be "
                                   "a positive length, got -50",
                          "where": {"link": 3, "field": "link 3, AB", "line": 23}}
    five = FOUR_BAR.replace('points = ["O4", "B"]', 'points = ["B", "C"]').replace(
        "lengths = { O4B = 200 }", "lengths = { BC = 200 }\n\n[[link]]\nnumber = 5\n"
        'points = ["O4", "C"]\nlengths = { O4C = 100 }').replace('B = "left"', "")
    r = client.post("/api/solve", json={"toml": five})
    assert r.status_code == 422
    assert "the mechanism has 2 degrees of freedom" in r.json()["error"]
    assert r.json()["where"]["field"] == "input" and "\n" not in r.json()["error"]
    toml = client.post("/api/solve", json={"toml": "name = [1,"})
    assert toml.status_code == 422 and toml.json()["error"].startswith("exercise.toml:1:")


@pytest.mark.parametrize("body, field", [({}, "toml"), ({"toml": "", "angle": "60"}, "angle"),
                                         ({"toml": "", "lang": "de"}, "lang"),
                                         ({"toml": "", "figures": "yes"}, "figures")])
def test_a_malformed_request_is_refused_naming_the_field(client, body, field):
    r = client.post("/api/solve", json=body)
    assert r.status_code == 400 and f'"{field}"' in r.json()["error"]


def test_another_chapter_is_solved_as_solve_solves_it(client, tmp_path):
    text = everything()["planetary-q1"].read_text(encoding="utf-8")
    got = client.post("/api/solve", json={"toml": text, "file": "planetary-q1.toml"}).json()
    out = _cli_solve(tmp_path, "planetary-q1")
    assert got["chapter"] == "gears" and got["omega"] == {}
    assert got["results"] == json.loads((out / "results.json").read_text(encoding="utf-8"))
    assert {f["name"] for f in got["figures"]} == {p.stem for p in out.glob("*.svg")} - {
        "solution"}
    r = client.post("/api/solve", json={"toml": text, "angle": 30})
    said = CliRunner().invoke(cli, ["solve", "planetary-q1", "--angle", "30"], prog_name="tarsim")
    assert r.status_code == 422 and said.exit_code == 1
    assert r.json()["error"] == said.output.strip().removeprefix("Error: ")


def test_download_gives_solves_files(client, tmp_path):
    out = _cli_solve(tmp_path, "four-bar")

    def download(**body):
        return client.post("/api/download", json={"toml": FOUR_BAR, **body})

    r = download(what="svg", figure="V_B-components")
    assert r.status_code == 200 and r.headers["content-type"].startswith("image/svg+xml")
    assert 'filename="V_B-components.svg"' in r.headers["content-disposition"]
    assert r.text == (out / "V_B-components.svg").read_text(encoding="utf-8")
    steps = download(what="steps")
    assert steps.text == (out / "steps.md").read_text(encoding="utf-8")
    assert download(what="toml", file="mine/fb.toml").content == FOUR_BAR.encode()
    assert 'filename="fb.toml"' in download(what="toml", file="mine/fb.toml").headers[
        "content-disposition"]
    missing = download(what="svg", figure="V_Z")
    assert missing.status_code == 404 and "centres, circle-diagram" in missing.json()["error"]
    assert download(what="gif").status_code == 400
    from tarsim.graphics.export import cairo_missing

    pdf = download(what="pdf", figure="centres")
    if cairo_missing():
        assert pdf.status_code == 503 and pdf.json()["error"] == cairo_missing()
    else:
        assert pdf.status_code == 200 and pdf.content.startswith(b"%PDF")
        png = download(what="png", figure="centres")
        assert png.content.startswith(b"\x89PNG") and png.headers["content-type"] == "image/png"


def test_the_page_is_one_document(client):
    r = client.get("/")
    assert r.status_code == 200 and r.headers["content-type"].startswith("text/html")
    page = r.text
    assert page.lstrip().startswith("<!DOCTYPE html>")
    assert "__JS__" not in page and "__CSS__" not in page
    assert "<script src=" not in page and "<link " not in page     # nothing fetched
    try:
        from tarsim.graphics.app_page import app_html
    except ImportError:         # before the page is installed: a page that says what is served
        assert "/api/solve" in page
    else:
        assert page == app_html()


def test_whole_false_leaves_out_only_the_mechanisms_own_answers(client):
    text = everything()["crank-shaper"].read_text(encoding="utf-8")
    full = client.post("/api/solve", json={"toml": text, "figures": False}).json()
    part = client.post("/api/solve", json={"toml": text, "figures": False,
                                           "whole": False}).json()
    assert {"dof", "time_ratio", "stroke"} <= set(full["results"]["quantities"])
    assert part["results"]["quantities"] == {}
    assert part["results"]["positions"] == full["results"]["positions"]
    assert part["omega"] == full["omega"] and part["velocities"] == full["velocities"]
    # an exercise that asks nothing at a position keeps what it asks
    rocker = everything()["grashof-crank-rocker"].read_text(encoding="utf-8")
    kept = client.post("/api/solve", json={"toml": rocker, "figures": False, "whole": False})
    assert "grashof" in kept.json()["results"]["quantities"]


def test_a_warm_app_lists_the_bundled_exercises_as_it_starts(folder):
    import threading

    from tarsim.exercises.serve import app as served

    for warm, listed in ((False, 0), (True, 1)):
        served._bundled.cache_clear()
        with TestClient(make_app(folder, warm=warm)):
            for t in threading.enumerate():
                if t.name == "tarsim-warm-up":
                    t.join(timeout=120)
            assert served._bundled.cache_info().currsize == listed


def test_figures_named_are_drawn_alone_with_their_steps(client, tmp_path):
    out = _cli_solve(tmp_path, "four-bar")
    got = client.post("/api/solve", json={"toml": FOUR_BAR, "figures": ["V_B-components"]}).json()
    assert [f["name"] for f in got["figures"]] == ["V_B-components"]
    assert got["figures"][0]["svg"] == (out / "V_B-components.svg").read_text(encoding="utf-8")
    assert got["figure_names"] == ["centres", "circle-diagram", "V_B-radius-rotation",
                                   "V_B-parallel-line", "V_B-components"]
    # its steps alone, numbered as steps.md numbers them; the results whole
    assert "<h2>V_B by components (<code>V_B-components.svg</code>)</h2>" in got["steps"]
    assert "Instant centres" not in got["steps"]
    whole = client.post("/api/solve", json={"toml": FOUR_BAR}).json()
    assert got["results"] == whole["results"] and got["table"] == whole["table"]
    assert whole["figure_names"] == [f["name"] for f in whole["figures"]]
    r = client.post("/api/solve", json={"toml": FOUR_BAR, "figures": [1]})
    assert r.status_code == 400 and '"figures"' in r.json()["error"]
