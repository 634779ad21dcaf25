"""camdyn serve: the live design page in the browser (Panel on Bokeh, runtime/cli/page.py)."""
from __future__ import annotations

import sys

from .common import fail

HELP = "the live design page in the browser: sliders, response, residual, cam, design rules"
"""The command's line in `camdyn --help`."""

PROG = "camdyn serve"


def add(sub):
    s = sub.add_parser("serve", help=HELP, description=(
        "Serve the design page on this machine: pick a mechanism (the one-DOF model, "
        "CAMSHAFT-1, -2, a DYNACAM scene), a follower and a law, move the sliders and see the "
        "response, U0'' against tau with the design point, the cam profile with its pressure "
        "angle and contact stress and the design rules' verdict, each figure with its error "
        "estimate; export the scene TOML, the cam DXF and a report.  Needs "
        "pip install 'camdyn[serve]'."))
    s.add_argument("--port", type=int, default=5006, help="port on 127.0.0.1 (default 5006; 0: "
                                                          "any free port, printed)")
    s.add_argument("--no-browser", action="store_true", help="do not open a browser tab")
    return s


def _free_port() -> int:
    """A port the system has free now (--port 0): the page's websocket accepts its own only."""
    import socket

    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def run(args) -> int:
    if not 0 <= args.port <= 65535:
        return fail(PROG, f"argument --port: {args.port} is out of range: 0 to 65535")
    try:
        import panel as pn
    except ImportError:
        return fail(PROG, "the page needs Panel: pip install 'camdyn[serve]'")
    from .page import app

    pn.extension()
    port = args.port or _free_port()
    try:
        server = pn.serve({"camdyn": app}, port=port, address="127.0.0.1",
                          show=False, start=False, title="camdyn design page",
                          websocket_origin=[f"127.0.0.1:{port}", f"localhost:{port}"],
                          threaded=False)
    except OSError as exc:
        return fail(PROG, f"argument --port: port {args.port} cannot be used ({exc.strerror}); "
                          "give another, or --port 0 for any free one")
    print(f"{PROG}: the design page is at http://127.0.0.1:{port}/camdyn (Ctrl-C stops it)",
          file=sys.stderr, flush=True)
    if not args.no_browser:
        server.io_loop.add_callback(server.show, "/camdyn")
    server.start()
    server.io_loop.start()
    return 0
