"""drafting serve, at the server: every request needs the token, this server's Host and (when sent) its own
Origin; only the served scenes are read or written; a save is atomic, keeps the previous version and is
refused (409) when the file changed since the tab loaded it; a bad scene answers with its one sentence,
the key and the line it names."""

from __future__ import annotations

import os
import shutil

import pytest

pytest.importorskip("starlette")
from starlette.testclient import TestClient  # noqa: E402

from drafting.serve.live import line_of  # noqa: E402
from drafting.serve.server import create_app  # noqa: E402
from drafting.serve.workspace import Conflict, Refused, Workspace  # noqa: E402
from paths import GALLERY  # noqa: E402

NAME = "notes-velocity-example-1.toml"
TOKEN = "test-token"


@pytest.fixture
def folder(tmp_path):
    shutil.copy(GALLERY / NAME, tmp_path / NAME)
    (tmp_path / "outside.toml").write_text("secret = 1\n")
    served = tmp_path / "served"
    served.mkdir()
    shutil.copy(GALLERY / NAME, served / NAME)
    return served


@pytest.fixture
def client(folder):
    with TestClient(create_app(folder, token=TOKEN), base_url="http://127.0.0.1:8470") as c:
        c.get(f"/?token={TOKEN}")                  # the first visit: the cookie
        yield c


def test_every_request_needs_the_token(folder):
    with TestClient(create_app(folder, token=TOKEN), base_url="http://127.0.0.1:8470") as c:
        for url in ("/", "/api/scenes", f"/api/scene?name={NAME}", "/api/events", "/view/x"):
            r = c.get(url)
            assert r.status_code == 403 and "needs its token" in r.text
        assert c.get("/api/scenes?token=wrong").status_code == 403
        assert c.post("/api/save", json={"name": NAME, "text": "x", "version": "0"}).status_code == 403
        r = c.get(f"/?token={TOKEN}")
        assert r.status_code == 200 and "HttpOnly" in r.headers["set-cookie"] and "SameSite=Strict" in r.headers["set-cookie"]
        assert c.get("/api/scenes").json() == {"scenes": [NAME]}        # the cookie from then on
        assert "frame-ancestors 'self'" in r.headers["content-security-policy"]


def test_another_host_or_origin_is_refused(client):
    r = client.get("/api/scenes", headers={"Host": "attacker.example:8470"})    # DNS rebinding
    assert r.status_code == 403 and "Host" in r.text
    r = client.post("/api/save", json={"name": NAME, "text": "", "version": "0"},
                    headers={"Origin": "http://attacker.example"})
    assert r.status_code == 403 and "attacker.example" in r.text
    assert client.get("/api/scenes", headers={"Origin": "http://127.0.0.1:8470"}).status_code == 200
    assert client.get("/api/scenes", headers={"Host": "localhost:8470", "Origin": "http://localhost:8470"}).status_code == 200


@pytest.mark.parametrize("name", ["../outside.toml", "/etc/passwd", "..", "sub/x.toml", "x.txt", "",
                                  "%2e%2e/outside.toml", "link.toml", "nul\x00.toml"])
def test_only_the_served_scenes_are_read_or_written(client, folder, name):
    os.symlink(folder.parent / "outside.toml", folder / "link.toml")          # a symlink leading out
    r = client.get("/api/scene", params={"name": name})
    assert r.status_code == 404 and "secret" not in r.text
    r = client.post("/api/save", json={"name": name, "text": "x = 1\n", "version": "0"})
    assert r.status_code == 400
    assert (folder.parent / "outside.toml").read_text() == "secret = 1\n"
    assert "link.toml" not in client.get("/api/scenes").json()["scenes"]


def test_one_scene_serves_that_scene_only(folder):
    (folder / "other.toml").write_text("x = 1\n")
    space = Workspace(folder / NAME)
    assert space.names() == [NAME]
    with pytest.raises(Refused):
        space.read("other.toml")


def test_a_save_is_atomic_keeps_a_backup_and_refuses_a_stale_version(client, folder):
    first = client.get("/api/scene", params={"name": NAME}).json()
    old = (folder / NAME).read_text()
    new = first["text"].replace('angle = "70 deg"', 'angle = "60 deg"')
    r = client.post("/api/save", json={"name": NAME, "text": new, "version": first["version"]})
    assert r.status_code == 200
    assert (folder / NAME).read_text() == new and (folder / (NAME + "~")).read_text() == old
    assert not [p for p in os.listdir(folder) if p.startswith(".drafting-tmp-")]       # no temporary left
    # a second tab, still at the first version, is told and nothing is overwritten
    r = client.post("/api/save", json={"name": NAME, "text": "stale", "version": first["version"]})
    assert r.status_code == 409 and "changed since this tab loaded it" in r.json()["error"]
    assert r.json()["version"] == client.get("/api/scene", params={"name": NAME}).json()["version"]
    assert (folder / NAME).read_text() == new
    # saving over it, knowingly, names the version it replaces
    r2 = client.post("/api/save", json={"name": NAME, "text": new + "\n", "version": r.json()["version"]})
    assert r2.status_code == 200 and (folder / (NAME + "~")).read_text() == new


def test_a_save_too_large_is_refused(folder):
    space = Workspace(folder)
    v = space.read(NAME).version
    with pytest.raises(Refused, match="larger than 256 KiB"):
        space.save(NAME, "#" * (300 * 1024), v)
    with pytest.raises(Conflict):
        space.save(NAME, "x = 1\n", "0" * 16)


def test_a_scene_is_drawn_or_told_at_its_line(client):
    text = client.get("/api/scene", params={"name": NAME}).json()["text"]
    good = client.post("/api/draw", json={"name": NAME, "text": text}).json()
    assert good["ok"] and good["sheets"] == 1 and any(r[0] == "V_C" for r in good["results"])
    # each row as the sheet prints it: quantity, graphical, analytic, difference
    assert all(len(r) == 4 and all(isinstance(c, str) for c in r) for r in good["results"]), good["results"][:2]
    page = client.get(f"/view/{good['id']}")
    assert page.status_code == 200 and "steps-data" in page.text
    for fmt, magic in (("svg", b"<svg"), ("pdf", b"%PDF"), ("png", b"\x89PNG")):
        r = client.get(f"/download/{good['id']}/x.{fmt}")
        assert r.status_code == 200 and r.content.startswith(magic), fmt
    bad = client.post("/api/draw", json={"name": NAME, "text": text.replace('"70 deg"', '"70 kg"')}).json()
    assert not bad["ok"] and bad["key"] == "input.angle" and bad["line"] == 39
    assert bad["error"] == f"{NAME}: input.angle: '70 kg' is not a value of angle (expected a unit like 'deg')"
    # the same limits as the CLI: a scene nested too deep is one sentence, nothing evaluated
    deep = client.post("/api/draw", json={"name": NAME, "text": "x = " + "[" * 5000}).json()
    assert not deep["ok"] and deep["error"].startswith(NAME)
    assert client.post("/api/draw", content=b"not json").status_code == 400


def test_the_line_an_error_names():
    text = "[[link]]\nlength = 1\n[[link]]\nnumber = 2\nlength = -5\n[input]\nangle = 3\n"
    assert line_of(text, "", "link[1].length") == 5
    assert line_of(text, "", "link[0].length") == 2
    assert line_of(text, "", "input.angle") == 7
    assert line_of(text, "", "input") == 6
    assert line_of(text, "x: is not valid TOML (Invalid value (at line 4, column 3))", "") == 4
    assert line_of(text, "", "") is None


def test_without_the_extra_the_command_says_how_to_install_it(monkeypatch, capsys):
    import drafting.serve.command as command
    from drafting.app.cli import main
    monkeypatch.setattr(command, "missing", lambda: ["starlette"])
    assert main(["serve", str(GALLERY / NAME)]) == 2
    err = capsys.readouterr().err.strip()
    assert err == "drafting: error: " + command.INSTALL and "\n" not in err
