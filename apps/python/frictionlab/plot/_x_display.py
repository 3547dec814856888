"""An X display for VTK to render in: Debian's VTK renders offscreen only through an X server, which
batch nodes and CI lack, so where $DISPLAY does not answer a private Xvfb is started, and always
stopped afterwards."""
import contextlib
import ctypes
import ctypes.util
import os
import select
import shutil
import signal
import subprocess
import tempfile


class RenderUnavailable(Exception):
    """VTK cannot render here; the message says why and what to install."""


def display_answers(name):
    """True if the X display `name` accepts a connection and offers GLX, as VTK's X render window
    needs: asked through Xlib first, since VTK aborts the whole process on a display it cannot open."""
    try:
        xlib = ctypes.CDLL(ctypes.util.find_library("X11") or "libX11.so.6")
    except OSError:
        return False
    xlib.XOpenDisplay.restype = ctypes.c_void_p
    xlib.XOpenDisplay.argtypes = [ctypes.c_char_p]
    xlib.XQueryExtension.argtypes = [ctypes.c_void_p, ctypes.c_char_p] + [ctypes.POINTER(ctypes.c_int)] * 3
    xlib.XCloseDisplay.argtypes = [ctypes.c_void_p]
    display = xlib.XOpenDisplay(name.encode())
    if not display:
        return False
    codes = [ctypes.c_int() for _ in range(3)]
    glx = xlib.XQueryExtension(display, b"GLX", *(ctypes.byref(c) for c in codes))
    xlib.XCloseDisplay(display)
    return bool(glx)


def stop_with_parent():
    """In a child before it starts: SIGTERM for it when this process ends, even killed (Linux's
    PR_SET_PDEATHSIG), so that no Xvfb outlives a plot stopped by a batch system."""
    ctypes.CDLL(None, use_errno=True).prctl(1, signal.SIGTERM)


@contextlib.contextmanager
def x_display():
    """An X display for the block: $DISPLAY if it answers, else a private Xvfb (Debian's VTK renders
    only through an X server, which batch nodes and CI lack), always stopped afterwards."""
    if os.environ.get("DISPLAY") and display_answers(os.environ["DISPLAY"]):
        yield
        return
    if not shutil.which("Xvfb"):
        raise RenderUnavailable("no X display, and no Xvfb to start one (Debian: xvfb)")
    # -displayfd: Xvfb takes a free display number itself (no collision with another run) and writes
    # it to the pipe once it accepts clients. -noreset: by default an X server resets when its last
    # client disconnects, and refuses connections meanwhile; VTK's SupportsOpenGL() connects and
    # disconnects just before the render connects again, which then failed at random (and VTK aborts).
    ready, number_fd = os.pipe()
    with tempfile.TemporaryFile() as log:
        server = subprocess.Popen(["Xvfb", "-displayfd", str(number_fd), "-screen", "0", "1600x1200x24",
                                   "-nolisten", "tcp", "-noreset"], pass_fds=(number_fd,), stdout=log, stderr=log,
                                  preexec_fn=stop_with_parent)
        os.close(number_fd)
        saved = os.environ.get("DISPLAY")
        try:
            with os.fdopen(ready) as f:  # Xvfb closes it, unwritten, if it fails
                number = f.readline().strip() if select.select([f], [], [], 30)[0] else ""
            if not number:
                log.seek(0)
                last = (log.read().decode(errors="replace").strip().splitlines() or ["no message"])[-1]
                raise RenderUnavailable(f"Xvfb did not start ({last})")
            os.environ["DISPLAY"] = ":" + number
            yield
        finally:
            if saved is None:
                os.environ.pop("DISPLAY", None)
            else:
                os.environ["DISPLAY"] = saved
            server.terminate()
            server.wait()
