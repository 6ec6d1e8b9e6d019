"""``tarsim serve``: a local app that opens, edits and solves exercises in the browser.

The server is a thin layer over the same calls the command line makes: a request's TOML
text is read as ``tarsim solve`` reads a file, solved by its chapter, and answered with
the figures as ``solve`` draws them, the steps, results.json's record and the table of
each number beside its analytic check (:mod:`.solving`). What it may touch is fenced in
by :mod:`.folder` (reads and writes inside the folder it was started in) and
:mod:`.body` (a request's size). The routes are :mod:`.app`'s; the contract with the
page is docs/howto/app.md's.

Starlette and uvicorn are the ``serve`` extra's (``pip install 'tarsim[serve]'``): this
package is imported only by the command that needs them.
"""

from __future__ import annotations

from .app import make_app

__all__ = ["make_app"]
