"""Where meshes are cached: a scene from another folder never writes into the checkout."""
import os

from shockfem.geometry.meshing import default_cache_dir

CHECKOUT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.realpath(__file__)))))


def test_a_scene_outside_the_checkout_caches_in_the_users_cache_folder(tmp_path, monkeypatch):
    monkeypatch.delenv("SHOCKFEM_MESH_CACHE", raising=False)
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "cache"))
    elsewhere = tmp_path / "my_scenes"
    assert default_cache_dir(str(elsewhere)) == str(tmp_path / "cache" / "shockfem" / "meshes")
    monkeypatch.delenv("XDG_CACHE_HOME")
    monkeypatch.setenv("HOME", str(tmp_path / "home"))
    assert default_cache_dir(str(elsewhere)) == str(tmp_path / "home" / ".cache" / "shockfem" / "meshes")


def test_the_checkouts_scenes_cache_in_its_meshes_folder_and_the_variable_wins(tmp_path, monkeypatch):
    monkeypatch.delenv("SHOCKFEM_MESH_CACHE", raising=False)
    assert default_cache_dir(os.path.join(CHECKOUT, "studies", "gallery")) == os.path.join(CHECKOUT, "meshes")
    monkeypatch.chdir(CHECKOUT)              # a scene built in code, from inside the checkout
    assert default_cache_dir("") == os.path.join(CHECKOUT, "meshes")
    monkeypatch.setenv("SHOCKFEM_MESH_CACHE", str(tmp_path / "mine"))
    assert default_cache_dir(str(tmp_path)) == str(tmp_path / "mine")


def test_a_scene_file_read_from_another_folder_carries_its_folder(tmp_path):
    from shockfem.scene import load_scene
    scene_file = tmp_path / "shrink.toml"
    scene_file.write_text(open(os.path.join(CHECKOUT, "studies", "gallery", "shrink_fit.toml")).read())
    assert load_scene(str(scene_file)).folder == str(tmp_path)
