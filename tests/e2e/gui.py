#!/usr/bin/env python3
"""GUI check of the "Low-stretch parameterization" filter in MeshLab under Xvfb.

  gui.py --prefix P --runner lowstretch_plugin_runner --mesh MESH.off --work DIR
      MeshLab 2020.09: the private prefix's meshlab, every system plugin and ours.
  gui.py --meshlab2025 BIN --io-plugin SO --plugin SO --mesh MESH.off --work DIR
      MeshLab 2025.07's GUI program, built from source, with its base I/O plugin and our float
      plugin only (in a private folder laid out as MeshLab looks for plugins).

Starts an Xvfb server and meshlab on MESH, opens Filters > Texture with the keyboard, selects the
filter, opens its dialog and presses Apply, then checks in MeshLab's log (which MeshLab also
prints on its output) that the filter ran and logged its metrics. For 2025.07 it also exports the
mesh (File > Export Mesh, a PLY) and checks the wedge texcoords written: one (u, v) per corner of
every face, inside [0,1]^2 by the gutter, no flipped triangle. Screenshots of every step are kept
in DIR (lowstretch_gui.png is the one after Apply); xdotool drives the GUI and ImageMagick's
`import` takes the pictures.
"""
import argparse
import hashlib
import os
import shutil
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import meshio  # noqa: E402

FILTER = "Low-stretch parameterization"
GUTTER = 2 / 1024  # the default gutter over the default texture size
TEXTURE_CLASS = 0x2000  # MeshFilterInterface::Texture


class Gui:
    def __init__(self, work):
        self.work = work
        self.env = dict(os.environ, HOME=os.path.join(work, "home"), XDG_RUNTIME_DIR=os.path.join(work, "runtime"))
        for key in ("HOME", "XDG_RUNTIME_DIR"):
            os.makedirs(self.env[key], mode=0o700)
        self.processes = []

    def start_xvfb(self):
        """Xvfb picks a free display itself and writes its number to a pipe (no race with other tests)."""
        read_end, write_end = os.pipe()
        xvfb = subprocess.Popen(["Xvfb", "-displayfd", str(write_end), "-screen", "0", "1600x1000x24", "-nolisten", "tcp",
                                 "-noreset"],
                                pass_fds=[write_end], stdout=subprocess.DEVNULL,
                                stderr=open(os.path.join(self.work, "xvfb.log"), "w"))
        self.processes.append(xvfb)
        os.close(write_end)
        with os.fdopen(read_end) as pipe:
            display = pipe.readline().strip()
        if not display:
            raise RuntimeError("Xvfb did not start")
        self.env["DISPLAY"] = ":" + display
        # Without -noreset the server resets whenever its last client disconnects (xdpyinfo below,
        # the runner): a client that connects during the reset is refused, as meshlab was
        # ("could not connect to display"). Wait until the server answers before starting anything.
        end = time.time() + 30
        while subprocess.run(["xdpyinfo"], env=self.env, capture_output=True).returncode != 0:
            if xvfb.poll() is not None or time.time() > end:
                raise RuntimeError(f"Xvfb on :{display} does not answer (exit code {xvfb.poll()})")
            time.sleep(0.2)

    def start(self, command, log_name):
        log = open(os.path.join(self.work, log_name), "w")
        process = subprocess.Popen(command, env=self.env, cwd=self.work, stdout=log, stderr=subprocess.STDOUT)
        self.processes.append(process)
        return process

    def run(self, *command):
        return subprocess.run(command, env=self.env, capture_output=True, text=True, timeout=60).stdout.strip()

    def window(self, name, timeout=30):
        """Id of the visible window whose title matches the regular expression `name`, or None:
        `xdotool search --sync` waits for it to appear, under coreutils' timeout. Debian 12's
        xdotool exits on BadWindow when any window closes during its search (a splash screen;
        xdotool issue 60, fixed after its release), so a failure before the timeout searches again."""
        end = time.time() + timeout
        while True:
            left = max(1, int(end - time.time()))
            command = ["timeout", str(left), "xdotool", "search", "--sync", "--onlyvisible", "--name", name]
            proc = subprocess.run(command, env=self.env, capture_output=True, text=True, timeout=left + 30)
            found = proc.stdout.split()
            if proc.returncode == 0 and found:
                return found[0]
            if time.time() >= end or proc.returncode == 124:  # 124: coreutils' timeout expired
                if proc.stderr.strip():
                    print(f"xdotool search {name!r}: {proc.stderr.strip()}")
                return None
            time.sleep(0.2)

    def settle(self, timeout=10):
        """Waits until the screen stops changing (two grabs 0.2 s apart are equal): the GUI has
        handled what it was sent and drawn the result. Returns False if it kept changing."""
        end = time.time() + timeout
        previous = None
        while time.time() < end:
            grab = subprocess.run(["import", "-window", "root", "-depth", "8", "rgb:-"], env=self.env,
                                  capture_output=True, timeout=60).stdout
            digest = hashlib.sha1(grab).hexdigest()
            if digest == previous:
                return True
            previous = digest
            time.sleep(0.2)
        return False

    def key(self, *keys):
        for key in keys:
            self.run("xdotool", "key", key)
            self.settle()

    def screenshot(self, name):
        path = os.path.join(self.work, name)
        self.run("import", "-window", "root", path)
        print(f"screenshot {path}")
        return path

    def stop(self):
        for process in reversed(self.processes):
            if process.poll() is None:
                process.terminate()
                try:
                    process.wait(timeout=10)
                except subprocess.TimeoutExpired:
                    process.kill()
                    process.wait()


def wait_for_text(path, texts, timeout):
    """Waits until the file holds one of `texts`; returns that text or None."""
    end = time.time() + timeout
    while time.time() < end:
        with open(path, errors="replace") as f:
            content = f.read()
        for text in texts:
            if text in content:
                return text
        time.sleep(0.5)
    return None


def open_filter_dialog(gui, check, keys):
    """Walks the menus with `keys` to Filters > Texture > the filter, opens its dialog; returns
    the dialog's window, or None (with a failed check and a screenshot)."""
    gui.key(*keys)
    gui.screenshot("02_filters_texture_menu.png")
    gui.key("Return")
    dialog = gui.window(f"^{FILTER}$", timeout=20)
    if not check(dialog is not None, "Filters > Texture > Low-stretch parameterization opens the filter's dialog"):
        gui.screenshot("03_no_dialog.png")
    return dialog


def run_2020(args, gui, check):
    """MeshLab 2020.09: Filters > Texture > the filter, Apply; returns 1 when it cannot go on."""
    gui.start_xvfb()
    # Where MeshLab puts the filter in Filters > Texture: filters of that class, sorted by name.
    plugins = os.path.join(args.prefix, "lib/x86_64-linux-gnu/meshlab/plugins")
    listing = subprocess.run([args.runner, "--list-filters", plugins], env=gui.env, capture_output=True,
                             text=True, timeout=120).stdout.splitlines()
    texture = sorted(name for cls, name in (line.split(" ", 1) for line in listing) if int(cls) & TEXTURE_CLASS)
    if not check(FILTER in texture, f"the plugin's filter is in the Texture class ({len(texture)} filters there)"):
        return 1
    index = texture.index(FILTER)

    log = os.path.join(args.work, "meshlab.log")
    gui.start([os.path.join(args.prefix, "bin", "meshlab"), os.path.abspath(args.mesh)], "meshlab.log")
    main_window = gui.window("^MeshLab 20")
    if not check(main_window is not None and wait_for_text(log, ["All files opened"], 60) is not None,
                 "meshlab starts and opens the mesh"):
        return 1
    gui.run("xdotool", "windowsize", main_window, "1120", "1000")  # no window manager: size it ourselves
    gui.run("xdotool", "windowfocus", "--sync", main_window)
    gui.settle()
    gui.screenshot("01_loaded.png")

    # Filters (Alt+L); Texture is the second last entry (Up from the top wraps to Camera, the
    # last); then down the Texture submenu to the filter.
    dialog = open_filter_dialog(gui, check, ["alt+l", "Up", "Up", "Right"] + ["Down"] * index)
    if dialog is None:
        return 1
    gui.run("xdotool", "windowmove", dialog, "1130", "0")  # beside the main window, not over the mesh
    gui.settle()
    gui.screenshot("03_dialog.png")

    gui.run("xdotool", "windowfocus", "--sync", dialog)
    gui.key("space")  # the dialog's Apply button has the focus
    outcome = wait_for_text(log, [f"Applied filter {FILTER}", "Filter failed"], 300)
    gui.settle()  # the view redrawn with the texture
    gui.screenshot("lowstretch_gui.png")
    with open(log, errors="replace") as f:
        text = f.read()
    check(outcome == f"Applied filter {FILTER}", f"Apply runs the filter and MeshLab reports success ({outcome})")
    check("pass 0: L2 stretch" in text and "kept pass" in text, "MeshLab's log holds the filter's metrics")
    check(gui.window("^Filter Failure", timeout=1) is None, "no failure message box")
    return 0


def private_meshlab2025(args):
    """A copy of MeshLab 2025.07's program beside a plugins/ folder with links to the base I/O
    plugin and ours: MeshLab loads the plugins found next to its program, so no other one."""
    folder = os.path.join(args.work, "meshlab2025")
    plugins = os.path.join(folder, "plugins")
    os.makedirs(plugins)
    program = os.path.join(folder, "meshlab")
    shutil.copy2(args.meshlab2025, program)  # its RUNPATH names the build's libraries
    for plugin in (args.io_plugin, args.plugin):
        os.symlink(os.path.abspath(plugin), os.path.join(plugins, os.path.basename(plugin)))
    return program


def run_2025(args, gui, check):
    """MeshLab 2025.07: Filters > Texture > the filter, Apply, then File > Export Mesh."""
    program = private_meshlab2025(args)
    mesh = os.path.join(args.work, "mesh.ply")  # a PLY, so that Export Mesh can write wedge texcoords
    vertices, faces = meshio.read_off(args.mesh)
    meshio.write_ply(mesh, vertices, faces)
    gui.start_xvfb()
    log = os.path.join(args.work, "meshlab.log")
    gui.start([program, mesh], "meshlab.log")
    question = gui.window("^Send Anonymous Statistics", timeout=60)  # asked once per new settings file
    if question is not None:
        gui.run("xdotool", "windowfocus", "--sync", question)
        gui.key("alt+n")
    main_window = gui.window("^MeshLab 2025", timeout=60)
    if not check(main_window is not None and wait_for_text(log, ["All files opened"], 60) is not None,
                 "MeshLab 2025.07 starts and opens the mesh"):
        return 1
    gui.run("xdotool", "windowsize", main_window, "1120", "1000")
    gui.run("xdotool", "windowfocus", "--sync", main_window)
    gui.settle()
    gui.screenshot("01_loaded.png")

    # Filters (Alt+L) opens on "Show current filter script" ("Apply filter" is disabled): Up wraps
    # to Other, then Camera, then Texture; with our plugin alone the filter is Texture's only entry.
    dialog = open_filter_dialog(gui, check, ["alt+l", "Up", "Up", "Up", "Right"])
    if dialog is None:
        return 1
    gui.settle()
    gui.screenshot("03_dialog.png")
    gui.run("xdotool", "windowfocus", "--sync", dialog)
    gui.key("space")  # Apply has the focus
    outcome = wait_for_text(log, [f"Applied filter: {FILTER}", "Failed to apply"], 300)
    gui.settle()
    gui.screenshot("lowstretch_gui.png")
    with open(log, errors="replace") as f:
        text = f.read()
    check(outcome == f"Applied filter: {FILTER}", f"Apply runs the filter and MeshLab reports success ({outcome})")
    check("pass 0: L2 stretch" in text and "kept pass" in text, "MeshLab's log holds the filter's metrics")

    # File > Export Mesh (Ctrl+E) writes mesh.ply again, after its saving options (OK by Return).
    before = os.path.getmtime(mesh)
    gui.run("xdotool", "windowfocus", "--sync", main_window)
    gui.key("ctrl+e")
    options = gui.window("^Choose Saving Options", timeout=20)
    if not check(options is not None, "File > Export Mesh asks for the saving options"):
        gui.screenshot("04_no_options.png")
        return 1
    gui.screenshot("04_saving_options.png")
    gui.run("xdotool", "windowfocus", "--sync", options)
    gui.key("Return")
    saved = wait_for_text(log, ["Saved Mesh"], 60)
    if not check(saved is not None and os.path.getmtime(mesh) > before, "the mesh is exported"):
        return 1
    check_texcoords(check, meshio.read_ply(mesh), len(faces))
    return 0


def check_texcoords(check, ply, face_count):
    """Wedge texcoords as the filter writes them: every corner, inside the gutter, no flip."""
    texcoords = ply.elements["face"].data.get("texcoord")
    if not check(texcoords is not None and len(texcoords) == face_count and all(len(t) == 6 for t in texcoords),
                 f"the exported PLY has wedge texcoords on all {face_count} faces"):
        return
    values = [x for t in texcoords for x in t]
    check(min(values) >= GUTTER - 1e-6 and max(values) <= 1 - GUTTER + 1e-6,
          f"wedge texcoords 2 texels of 1024 inside [0,1]^2: [{min(values):.6g}, {max(values):.6g}]")
    bad = sum(1 for t in texcoords if not (t[2] - t[0]) * (t[5] - t[1]) - (t[4] - t[0]) * (t[3] - t[1]) > 0)
    check(bad == 0, f"no flipped or zero-area UV triangle ({bad})")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--prefix", help="2020.09: the private MeshLab prefix with our plugin")
    parser.add_argument("--runner", help="2020.09: lowstretch_plugin_runner (lists the Texture filters)")
    parser.add_argument("--meshlab2025", help="2025.07: MeshLab's GUI program, built from source")
    parser.add_argument("--io-plugin", help="2025.07: MeshLab's libio_base.so")
    parser.add_argument("--plugin", help="2025.07: our float plugin")
    parser.add_argument("--mesh", required=True)
    parser.add_argument("--work", required=True)
    args = parser.parse_args()
    if not (args.prefix and args.runner) and not (args.meshlab2025 and args.io_plugin and args.plugin):
        parser.error("give --prefix and --runner (2020.09), or --meshlab2025, --io-plugin and --plugin (2025.07)")
    shutil.rmtree(args.work, ignore_errors=True)
    os.makedirs(args.work)
    failed = []

    def check(ok, what):
        print(("ok:     " if ok else "FAILED: ") + what)
        if not ok:
            failed.append(what)
        return ok

    gui = Gui(args.work)
    try:
        code = (run_2025 if args.meshlab2025 else run_2020)(args, gui, check)
    finally:
        gui.stop()
    print(f"{len(failed)} check(s) failed" if failed else "all checks passed")
    return 1 if failed or code else 0


if __name__ == "__main__":
    sys.exit(main())
