"""animate_run.py and `ancfnet animate`: a GIF with one frame per chosen output, clear errors."""

import math
import shutil
import subprocess

import pytest
from PIL import Image

from animate_run import has_ffmpeg
from vtk_frames import read_frames


def gif_frames(path):
    with Image.open(path) as image:
        return image.n_frames


def test_gif_has_one_frame_per_kth_output(cli, capture_run, tmp_path):
    outputs = len(read_frames(capture_run))
    for every in (2, 5):
        movie = tmp_path / f"every{every}.gif"
        finished = cli("animate", capture_run, "-o", movie, "--every", every, "--view", "top")
        assert finished.returncode == 0, finished.stderr
        assert gif_frames(movie) == math.ceil(outputs / every)
        assert f"{math.ceil(outputs / every)} frames" in finished.stdout


def test_default_movie_lands_in_the_run_folder(cli, run_copy):
    finished = cli("animate", run_copy, "--every", "4")
    assert finished.returncode == 0, finished.stderr
    expected = run_copy / ("animation.mp4" if has_ffmpeg() else "animation.gif")
    assert expected.stat().st_size > 0


def test_frames_hold_the_net_and_the_body_axes(capture_run):
    first, last = read_frames(capture_run, [0.0, 0.06])
    assert len(first.threads) == len(last.threads) == 2 * 4 * 5  # 4 × 4 meshes: 40 threads
    assert len(first.bodies) == 1
    body = first.bodies[0]
    assert body.origin == pytest.approx([0, 0, 0], abs=1e-12)
    lengths = [math.dist(body.origin, tip) for tip in body.axis_tips]
    assert lengths == pytest.approx([lengths[0]] * 3)


def test_without_ffmpeg_the_default_is_a_gif_and_mp4_is_refused(cli, run_copy, tmp_path):
    no_ffmpeg = {"PATH": str(tmp_path / "empty")}  # matplotlib looks for ffmpeg on PATH
    finished = cli("animate", run_copy, "-o", tmp_path / "movie.mp4", env=no_ffmpeg)
    assert finished.returncode == 2
    assert "writing MP4 needs ffmpeg (Debian package ffmpeg" in finished.stderr
    finished = cli("animate", run_copy, "--every", "6", env=no_ffmpeg)
    assert finished.returncode == 0, finished.stderr
    assert gif_frames(run_copy / "animation.gif") == 3


@pytest.mark.skipif(not has_ffmpeg() or not shutil.which("ffprobe"),
                    reason="no ffmpeg (scripts/install-deps.sh --video)")
def test_mp4_has_one_frame_per_kth_output(cli, capture_run, tmp_path):
    movie = tmp_path / "movie.mp4"
    finished = cli("animate", capture_run, "-o", movie, "--every", "3")
    assert finished.returncode == 0, finished.stderr
    counted = subprocess.run(
        ["ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
         "stream=nb_read_frames", "-of", "csv=p=0", movie], capture_output=True, text=True)
    assert int(counted.stdout) == math.ceil(len(read_frames(capture_run)) / 3)
