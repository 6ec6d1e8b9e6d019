"""``tarsim serve``: the app in the browser, served from this machine.

A command of its own module, as ``handout`` is: it needs the ``serve`` extra (starlette
and uvicorn), which it looks for first, so that without it the user reads one line
saying what to install rather than a traceback; and its socket is bound here, before the
server starts, so that a port in use is said in one line too.
"""

from __future__ import annotations

import socket
from pathlib import Path

import click

__all__ = ["serve"]

_LOCAL = ("127.0.0.1", "localhost", "::1")


@click.command()
@click.argument("folder", type=click.Path(exists=True, file_okay=False), default=".",
                metavar="[FOLDER]")
@click.option("--host", default="127.0.0.1", show_default=True,
              help="The address to listen on. Only this machine can reach 127.0.0.1; "
                   "0.0.0.0 opens the app (and FOLDER) to the network.")
@click.option("--port", type=click.IntRange(0, 65535), default=8765, show_default=True,
              help="The port to listen on (0: any free one, printed).")
@click.option("--no-browser", is_flag=True, help="Do not open the app in the browser.")
def serve(folder, host, port, no_browser):
    """Open the app: build a mechanism by clicking, turn it, see it solved.

    Starts a local server and opens its page in the browser. The page opens
    any bundled exercise, or a .toml file in FOLDER (default: here), and
    shows the worked solution as `tarsim solve` makes it: each figure, the
    numbered steps and the results beside the analytic check, redrawn as
    the input turns or a length changes, with the same one-line error as
    the command line for a mechanism that cannot be put together. It
    downloads the TOML file, the figures (SVG, PDF, PNG) and the steps,
    and saves the exercise in FOLDER. The server reads and writes nothing
    outside FOLDER; Ctrl+C stops it.

    Needs the serve extra: pip install 'tarsim[serve]'.

    \b
    Example:
      tarsim serve                      # this folder, at http://127.0.0.1:8765/
      tarsim serve exercises/ --port 9000 --no-browser
    """
    try:
        import uvicorn

        from .serve import make_app
    except ImportError:
        raise click.ClickException("tarsim serve needs the serve extra: "
                                   "pip install 'tarsim[serve]'") from None
    if host not in _LOCAL:
        click.echo(f"warning: listening on {host}: anyone who can reach this machine can "
                   f"open the app and read and write the .toml files of {folder}", err=True)
    sock = _listening(host, port)
    url = f"http://{_shown(host)}:{sock.getsockname()[1]}/"
    # A page of another site reaching this server by a name of its own is refused.
    hosts = None if ":" in host or host == "0.0.0.0" else [host, *_LOCAL[:2]]
    app = make_app(Path(folder), hosts=hosts, warm=True)
    click.echo(f"tarsim serve: {url} (serving {Path(folder).resolve()}; Ctrl+C stops it)")
    if not no_browser:
        import webbrowser

        webbrowser.open(url)
    server = uvicorn.Server(uvicorn.Config(app, log_level="warning"))
    server.run(sockets=[sock])


def _listening(host: str, port: int) -> socket.socket:
    """A socket bound to ``host``:``port`` and listening, or one line saying why not."""
    sock = None
    try:
        family = socket.getaddrinfo(host, port, type=socket.SOCK_STREAM)[0][0]
        sock = socket.socket(family, socket.SOCK_STREAM)
        sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        sock.bind((host, port))
        sock.listen(128)
    except OSError as e:
        if sock is not None:
            sock.close()
        raise click.ClickException(f"cannot listen on {host}:{port}: {e.strerror or e}; "
                                   "choose another --port (or --port 0 for any free one)"
                                   ) from None
    return sock


def _shown(host: str) -> str:
    """``host`` as a URL names it: the wildcard as this machine, IPv6 in brackets."""
    if host in ("0.0.0.0", "::"):
        return "127.0.0.1"
    return f"[{host}]" if ":" in host else host
