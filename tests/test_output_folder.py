"""Tests for output folders (graphics.atomic_files.write_folder, check_folder): all or nothing,
one solution per folder, the user's files never touched, concurrent runs serialised, and a
bad ``-o`` refused before the solve.
"""

import errno
import fcntl
import json
import multiprocessing
import os
import threading

import pytest
from click.testing import CliRunner

from tarsim.exercises.cli import cli
from tarsim.graphics import atomic_files
from tarsim.graphics.export import MANIFEST, RenderError, check_folder, output_folder, write_folder

FIRST = {"centres.svg": "<svg>first</svg>", "steps.md": "# first\n", "results.json": "{}\n",
         "centres.pdf": b"%PDF-first"}
SECOND = {"worked.svg": "<svg>second</svg>", "steps.md": "# second\n",
          "results.json": '{"second": true}\n'}


def run(*args):
    return CliRunner().invoke(cli, [str(a) for a in args], prog_name="tarsim",
                              catch_exceptions=False)


def assert_one_line_error(result) -> str:
    assert result.exit_code == 1, result.output
    assert result.stdout == ""
    err = result.stderr
    assert err.startswith("Error: ") and err.endswith("\n") and err.count("\n") == 1, err
    assert "Traceback" not in err
    return err


def snapshot(folder):
    """Every entry of ``folder`` (hidden ones too) by name: a file's bytes, or "<dir>"."""
    return {p.name: p.read_bytes() if p.is_file() else "<dir>" for p in folder.iterdir()}


def manifest(folder):
    return json.loads((folder / MANIFEST).read_text(encoding="utf-8"))


def as_bytes(files):
    return {n: d.encode("utf-8") if isinstance(d, str) else d for n, d in files.items()}


# ----- one set, with its manifest ----------------------------------------------------------------
def test_writes_the_set_and_a_manifest_naming_it(tmp_path):
    out = tmp_path / "a" / "b"                    # made, parents too
    written = write_folder(FIRST, out)
    assert written == [out / n for n in FIRST]
    assert snapshot(out) == {**as_bytes(FIRST), MANIFEST: (out / MANIFEST).read_bytes()}
    assert manifest(out) == sorted(FIRST)


def test_a_second_run_replaces_the_first_whole_and_keeps_the_users_files(tmp_path):
    write_folder(FIRST, tmp_path)
    (tmp_path / "notes.txt").write_text("mine", encoding="utf-8")
    (tmp_path / "drafts").mkdir()
    write_folder(SECOND, tmp_path)
    names = set(snapshot(tmp_path))
    assert names == {*SECOND, MANIFEST, "notes.txt", "drafts"}   # centres.* are gone
    assert (tmp_path / "notes.txt").read_text(encoding="utf-8") == "mine"
    assert (tmp_path / "steps.md").read_text(encoding="utf-8") == "# second\n"
    assert manifest(tmp_path) == sorted(SECOND)


def test_a_users_file_of_the_same_name_is_refused_and_nothing_moves(tmp_path):
    write_folder(FIRST, tmp_path)
    (tmp_path / "worked.svg").write_text("the user's own", encoding="utf-8")
    before = snapshot(tmp_path)
    with pytest.raises(RenderError) as info:
        write_folder(SECOND, tmp_path)
    assert str(info.value) == (
        f"cannot write '{tmp_path / 'worked.svg'}': a file of that name is already there and "
        "tarsim did not write it; move it or choose another folder with -o")
    assert snapshot(tmp_path) == before           # the first set whole, no staging folder


def test_a_folder_with_no_manifest_holds_only_the_users_files(tmp_path):
    (tmp_path / "steps.md").write_text("my notes", encoding="utf-8")
    with pytest.raises(RenderError, match="tarsim did not write it"):
        write_folder(FIRST, tmp_path)
    assert snapshot(tmp_path) == {"steps.md": b"my notes"}


def test_an_unreadable_manifest_counts_nothing_as_tarsims(tmp_path):
    write_folder(FIRST, tmp_path)
    (tmp_path / MANIFEST).write_text("not json", encoding="utf-8")
    write_folder({"other.svg": "<svg/>"}, tmp_path)   # removes nothing it cannot vouch for
    assert set(snapshot(tmp_path)) == {*FIRST, "other.svg", MANIFEST}
    with pytest.raises(RenderError, match="tarsim did not write it"):
        write_folder({"steps.md": "x"}, tmp_path)


def test_a_manifest_cannot_make_it_remove_anything_outside_the_folder(tmp_path):
    out = tmp_path / "out"
    write_folder(FIRST, out)
    (tmp_path / "precious.txt").write_text("keep", encoding="utf-8")
    (out / MANIFEST).write_text(json.dumps(["../precious.txt", *FIRST]), encoding="utf-8")
    write_folder(SECOND, out)
    assert (tmp_path / "precious.txt").read_text(encoding="utf-8") == "keep"
    assert set(snapshot(out)) == {*SECOND, MANIFEST}


@pytest.mark.parametrize("name", ["../x.svg", "sub/../x.svg", "sub//x.svg", "/x.svg", "sub/",
                                  "", "..", MANIFEST, f"{MANIFEST}/x", ".tarsim-x",
                                  ".tarsim-x/y.svg"])
def test_a_name_that_is_not_a_plain_file_name_is_refused(tmp_path, name):
    with pytest.raises(RenderError, match="not a plain file name"):
        write_folder({name: "x"}, tmp_path / "out")
    assert not (tmp_path / "out").exists()


# ----- all or nothing -------------------------------------------------------------------------
@pytest.mark.parametrize("after", [0, 1, 2])
def test_a_full_disk_while_staging_leaves_the_folder_as_it_was(tmp_path, monkeypatch, after):
    write_folder(FIRST, tmp_path)
    (tmp_path / "notes.txt").write_text("mine", encoding="utf-8")
    before = snapshot(tmp_path)
    real, calls = atomic_files._put, []

    def fills_up(path, data):
        calls.append(path.name)
        if len(calls) > after:
            raise OSError(errno.ENOSPC, "No space left on device")
        real(path, data)
    monkeypatch.setattr(atomic_files, "_put", fills_up)
    with pytest.raises(RenderError) as info:
        write_folder(SECOND, tmp_path)
    failed = list(SECOND)[after]
    assert str(info.value) == f"cannot write '{tmp_path / failed}': No space left on device"
    assert snapshot(tmp_path) == before           # no staging folder, old files intact


def test_a_failed_manifest_write_moves_nothing(tmp_path, monkeypatch):
    # The manifest naming old and new goes first, under the lock: if it cannot be written
    # (the disk filled meanwhile), no file has moved yet.
    write_folder(FIRST, tmp_path)
    before = snapshot(tmp_path)
    real = atomic_files._put

    def no_manifest(path, data):
        if path.name.startswith(".tarsim-"):
            raise OSError(errno.ENOSPC, "No space left on device")
        real(path, data)
    monkeypatch.setattr(atomic_files, "_put", no_manifest)
    with pytest.raises(RenderError, match="No space left on device"):
        write_folder(SECOND, tmp_path)
    assert snapshot(tmp_path) == before


# ----- concurrent runs ------------------------------------------------------------------------
def test_concurrent_writers_leave_one_whole_set(tmp_path):
    sets = {w: {**{f"{w}-{i}.svg": f"<svg>{w}{i}</svg>" for i in range(6)},
                "steps.md": f"# {w}\n"} for w in ("a", "b")}
    start, errors = threading.Barrier(2), []

    def writer(w):
        start.wait()
        try:
            for _ in range(30):
                write_folder(sets[w], tmp_path)
        except Exception as e:                    # noqa: BLE001 - reported below
            errors.append(e)
    threads = [threading.Thread(target=writer, args=(w,)) for w in sets]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert errors == []
    names = set(snapshot(tmp_path))
    winner = next(w for w in sets if set(sets[w]) | {MANIFEST} == names)
    assert manifest(tmp_path) == sorted(sets[winner])
    assert snapshot(tmp_path)["steps.md"] == f"# {winner}\n".encode()


def test_a_writer_never_removes_the_staging_folder_another_process_is_filling(tmp_path):
    # Each writer removes the staging folders it finds unlocked; a live one is locked.
    # Separate processes, so each lock is another process's, as between two runs.
    sets = {w: {f"{w}-{i}.svg": f"<svg>{w}{i}</svg>" * 2000 for i in range(8)} for w in "ab"}
    ctx = multiprocessing.get_context("fork")
    with ctx.Pool(2) as pool:
        failures = pool.starmap(_write_many, [(sets[w], str(tmp_path), 25) for w in sets])
    assert failures == [[], []]
    names = set(snapshot(tmp_path))
    assert any(names == {*sets[w], MANIFEST} for w in sets), names


def _write_many(files, out, times):
    failures = []
    for _ in range(times):
        try:
            write_folder(files, out)
        except RenderError as e:
            failures.append(str(e))
    return failures


# ----- a kill mid-commit, and links -------------------------------------------------------------
def stale_stage(out, name=".tarsim-k1ll3d_x"):
    """A staging folder as a run killed during its commit leaves it: mode 0700 (mkdtemp's),
    some staged files not yet moved, the first manifest's temporary."""
    stage = out / name
    stage.mkdir(mode=0o700)
    (stage / "steps.md").write_text("# staged\n", encoding="utf-8")
    (stage / "sub").mkdir()
    (stage / "sub" / "x.svg").write_text("<svg/>", encoding="utf-8")
    return stage


def test_the_next_run_removes_a_killed_runs_staging_folder(tmp_path):
    write_folder(FIRST, tmp_path)
    stale_stage(tmp_path)
    write_folder(SECOND, tmp_path)
    assert set(snapshot(tmp_path)) == {*SECOND, MANIFEST}


def test_a_staging_folder_in_use_is_kept(tmp_path):
    # Locked as a live run locks its own: the lock, not the age, tells a dead run's.
    stage = stale_stage(tmp_path)
    fd = os.open(stage, os.O_RDONLY)
    try:
        fcntl.flock(fd, fcntl.LOCK_EX)
        write_folder(FIRST, tmp_path)
        assert (stage / "steps.md").read_text(encoding="utf-8") == "# staged\n"
    finally:
        os.close(fd)
    write_folder(FIRST, tmp_path)                 # unlocked now: its run is gone
    assert set(snapshot(tmp_path)) == {*FIRST, MANIFEST}


@pytest.mark.parametrize("name, make", [
    (".tarsim-k1ll3d_x", "link"),                 # a link named as a staging folder
    (".tarsim-k1ll3d_x", "mode 0755"),            # not mkdtemp's mode: the user's
    (".tarsim-k1ll3d_x", "file"),
    (".tarsim-users-own", "folder"),              # not mkdtemp's name
])
def test_what_only_looks_like_a_staging_folder_is_kept(tmp_path, name, make):
    out, outside = tmp_path / "out", tmp_path / "outside"
    out.mkdir()
    outside.mkdir(mode=0o700)
    (outside / "keep.txt").write_text("keep", encoding="utf-8")
    if make == "link":
        (out / name).symlink_to(outside)
    elif make == "file":
        (out / name).write_text("mine", encoding="utf-8")
    else:
        (out / name).mkdir(mode=0o755 if make == "mode 0755" else 0o700)
        os.chmod(out / name, 0o755 if make == "mode 0755" else 0o700)
    write_folder(FIRST, out)
    assert os.path.lexists(out / name)
    assert (outside / "keep.txt").read_text(encoding="utf-8") == "keep"


def test_names_may_lead_through_folders_made_inside(tmp_path):
    files = {"ali/grade.json": "{}", "ali/grade.svg": "<svg/>", "a_b/grade.json": "{}",
             "grades.csv": "name\n"}
    write_folder(files, tmp_path)
    assert manifest(tmp_path) == sorted(files)
    assert (tmp_path / "ali" / "grade.svg").read_text(encoding="utf-8") == "<svg/>"
    (tmp_path / "a_b" / "notes.txt").write_text("mine", encoding="utf-8")
    write_folder({"grades.csv": "name\n"}, tmp_path)
    # ali/ held only tarsim's files and is gone; a_b/ holds the user's and is kept.
    assert set(snapshot(tmp_path)) == {"grades.csv", "a_b", MANIFEST}
    assert set(snapshot(tmp_path / "a_b")) == {"notes.txt"}


def test_a_name_that_is_a_file_and_a_folder_is_refused(tmp_path):
    with pytest.raises(RenderError) as info:
        write_folder({"ali": "x", "ali/grade.json": "{}"}, tmp_path / "out")
    assert str(info.value) == ("cannot write 'ali/grade.json': 'ali' is one of the files, so "
                               "it cannot be a folder too")
    assert not (tmp_path / "out").exists()


def test_a_file_where_a_folder_goes_is_refused_and_nothing_moves(tmp_path):
    write_folder(FIRST, tmp_path)
    (tmp_path / "ali").write_text("mine", encoding="utf-8")
    before = snapshot(tmp_path)
    with pytest.raises(RenderError) as info:
        write_folder({"ali/grade.json": "{}", "steps.md": "x"}, tmp_path)
    assert str(info.value) == (f"cannot write into '{tmp_path / 'ali'}': it is a file, not a "
                               "folder; move it or choose another folder with -o")
    assert snapshot(tmp_path) == before


def test_a_link_inside_the_folder_is_never_written_through(tmp_path):
    # A link planted where a student's folder goes, pointing out of the output folder.
    out, outside = tmp_path / "graded", tmp_path / "outside"
    outside.mkdir()
    write_folder({"grades.csv": "name\n"}, out)
    (out / "a_b").symlink_to(outside)
    before = snapshot(out)
    with pytest.raises(RenderError) as info:
        write_folder({"a_b/grade.json": "{}", "grades.csv": "name\na_b\n"}, out)
    assert str(info.value) == (f"cannot write into '{out / 'a_b'}': it is a symbolic link, and "
                               "tarsim writes only inside the output folder; remove it")
    assert list(outside.iterdir()) == []
    assert snapshot(out) == before


def test_a_link_put_where_tarsims_folder_was_is_not_followed_to_remove(tmp_path):
    out, outside = tmp_path / "graded", tmp_path / "outside"
    outside.mkdir()
    (outside / "grade.json").write_text("not tarsim's", encoding="utf-8")
    write_folder({"a_b/grade.json": "{}"}, out)
    for f in (out / "a_b").iterdir():
        f.unlink()
    (out / "a_b").rmdir()
    (out / "a_b").symlink_to(outside)             # the last run's folder, now a link out
    write_folder({"grades.csv": "name\n"}, out)
    assert (outside / "grade.json").read_text(encoding="utf-8") == "not tarsim's"
    assert (out / "a_b").is_symlink() and manifest(out) == ["grades.csv"]


def test_a_link_that_is_a_file_of_the_set_is_replaced_not_followed(tmp_path):
    out, outside = tmp_path / "out", tmp_path / "outside.svg"
    outside.write_text("not tarsim's", encoding="utf-8")
    write_folder(FIRST, out)
    (out / "centres.svg").unlink()
    (out / "centres.svg").symlink_to(outside)     # listed in the manifest as tarsim's
    write_folder(FIRST, out)
    assert not (out / "centres.svg").is_symlink()
    assert outside.read_text(encoding="utf-8") == "not tarsim's"


# ----- the folder checked before a solve ------------------------------------------------------
def test_check_folder_makes_the_folder_and_leaves_it_empty(tmp_path):
    out = tmp_path / "new" / "deeper"
    check_folder(out)
    assert out.is_dir() and list(out.iterdir()) == []


@pytest.mark.parametrize("where, message", [
    ("file", "cannot write into '{p}': it is a file, not a folder"),
    ("file/sub", "cannot make the folder '{p}': '{t}/file' is a file"),
])
def test_check_folder_refuses_a_file(tmp_path, where, message):
    (tmp_path / "file").write_text("mine", encoding="utf-8")
    with pytest.raises(RenderError) as info:
        check_folder(tmp_path / where)
    assert str(info.value) == message.format(p=tmp_path / where, t=tmp_path)
    assert snapshot(tmp_path) == {"file": b"mine"}


def test_check_folder_refuses_proc():
    with pytest.raises(RenderError, match="^cannot make the folder '/proc/tarsim-test': "):
        check_folder("/proc/tarsim-test")


def test_check_folder_proves_the_folder_writable(tmp_path, monkeypatch):
    def refuse(*args, **kwargs):
        raise PermissionError(errno.EACCES, "Permission denied")
    monkeypatch.setattr(atomic_files.tempfile, "mkstemp", refuse)
    out = tmp_path / "out"
    with pytest.raises(RenderError) as info:
        check_folder(out)
    assert str(info.value) == f"cannot write into the folder '{out}': Permission denied"
    assert not out.exists()                       # made by the check, so removed again


def test_output_folder_removes_what_it_made_when_the_body_fails(tmp_path):
    out = tmp_path / "a" / "b"
    with pytest.raises(ValueError), output_folder(out):
        assert out.is_dir()
        raise ValueError("the solve failed")
    assert list(tmp_path.iterdir()) == []
    (tmp_path / "kept").mkdir()
    with pytest.raises(ValueError), output_folder(tmp_path / "kept"):
        raise ValueError("the solve failed")
    assert (tmp_path / "kept").is_dir()           # it was there before


# ----- the command line -------------------------------------------------------------------------
@pytest.fixture
def no_solve(monkeypatch):
    """Make solving or sweeping fail loudly: the folder must be refused before either."""
    from tarsim.exercises.linkages import solution_files, sweep

    def called(*args, **kwargs):
        raise AssertionError("the solve ran before the folder was checked")
    monkeypatch.setattr(solution_files, "solve_worked", called)
    monkeypatch.setattr(sweep, "sweep_exercise", called)


@pytest.mark.parametrize("command", ["solve", "sweep"])
def test_an_output_under_proc_fails_in_one_line_before_solving(no_solve, command):
    err = assert_one_line_error(run(command, "four-bar", "-o", "/proc/tarsim-test", "--no-pdf"))
    assert err.startswith("Error: cannot make the folder '/proc/tarsim-test': ")


@pytest.mark.parametrize("command", ["solve", "sweep"])
def test_an_output_that_is_a_file_fails_in_one_line_before_solving(tmp_path, no_solve, command):
    path = tmp_path / "afile"
    path.write_text("mine", encoding="utf-8")
    err = assert_one_line_error(run(command, "four-bar", "-o", path, "--no-pdf"))
    assert err == f"Error: cannot write into '{path}': it is a file, not a folder\n"
    assert path.read_text(encoding="utf-8") == "mine"


@pytest.mark.slow
def test_solving_another_exercise_into_the_folder_replaces_the_solution(tmp_path):
    out = tmp_path / "out"
    out.mkdir()
    (out / "notes.txt").write_text("mine", encoding="utf-8")
    assert run("solve", "four-bar", "-o", out, "--no-pdf").exit_code == 0
    four_bar = set(manifest(out))
    assert "centres.svg" in four_bar and four_bar <= set(snapshot(out))
    result = run("solve", "inverted-slider-crank", "-o", out, "--no-pdf")
    assert result.exit_code == 0, result.output
    assert f"wrote {len(manifest(out))} files to {out}/" in result.stdout
    assert set(snapshot(out)) == {*manifest(out), MANIFEST, "notes.txt"}
    assert not (four_bar - set(manifest(out))) & set(snapshot(out))   # no four-bar figures
    assert (out / "notes.txt").read_text(encoding="utf-8") == "mine"
    assert '"exercise": "inverted-slider-crank"' in (out / "results.json").read_text("utf-8")


@pytest.mark.slow
def test_solve_refuses_to_replace_a_users_file(tmp_path):
    out = tmp_path / "out"
    out.mkdir()
    (out / "steps.md").write_text("my own steps", encoding="utf-8")
    err = assert_one_line_error(run("solve", "four-bar", "-o", out, "--no-pdf"))
    assert err == (f"Error: cannot write '{out / 'steps.md'}': a file of that name is already "
                   "there and tarsim did not write it; move it or choose another folder "
                   "with -o\n")
    assert snapshot(out) == {"steps.md": b"my own steps"}


@pytest.mark.slow
def test_worked_solution_write_goes_through_the_same_path(tmp_path, solved):
    worked = solved("four-bar")
    (tmp_path / "results.json").write_text("mine", encoding="utf-8")
    with pytest.raises(RenderError, match="tarsim did not write it"):
        worked.write(tmp_path, pdf=False)
    (tmp_path / "results.json").unlink()
    written = worked.write(tmp_path, pdf=False)
    assert sorted(p.name for p in written) == manifest(tmp_path) == sorted(worked.files())
