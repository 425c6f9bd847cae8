"""A chapter's explorer (chNN --explore) started for a test, and asked things over HTTP with
Python's http.client, with its token as the page sends it (the X-Rtlab-Token header) unless a
test says otherwise. Shared by tests/explore_*_test.py."""
import http.client
import subprocess
import tempfile


def ball_scene(name):
    """A scene of one ball named `name`, filling the middle of the view, shaded with a ray tree
    (whitted): a click at the centre picks it, and its side view names it."""
    return {"camera": {"eye": [0, 0, 5], "target": [0, 0, 0], "fov": 40}, "shading": "whitted",
            "lights": [{"type": "point", "position": [2, 3, 4], "color": [1, 1, 1]}],
            "materials": {"m": {"diffuse": [0.8, 0.3, 0.2]}},
            "surfaces": [{"type": "sphere", "center": [0, 0, 0], "radius": 1.5, "material": "m", "name": name}]}


class Explorer:
    def __init__(self, program, *args):
        """Starts `program --explore ARGS` and reads the address it prints. Its stderr goes to a
        file, which no amount of it can fill and stall the server."""
        self.errors = tempfile.TemporaryFile("w+")
        self.process = subprocess.Popen([str(program), "--explore", *map(str, args)], stdout=subprocess.PIPE,
                                        stderr=self.errors, text=True)
        self.line = self.process.stdout.readline()
        self.url = self.line.split(" at ")[1].split()[0] if " at http://127.0.0.1:" in self.line else None
        self.port = int(self.url.split(":")[2].split("/")[0]) if self.url else None
        self.token = self.url.split("?token=")[1] if self.url and "?token=" in self.url else ""
        self.origin = f"http://127.0.0.1:{self.port}"

    def request(self, method, path, body=None, headers=None, token=True, host=True, timeout=30):
        """(status, headers, bytes) of one request on a connection of its own. `token`: True for
        the explorer's, False for none, or a string to send instead; `host`: True for
        127.0.0.1:PORT, None for no Host header, or a string to send instead."""
        sent = dict(headers or {})
        if token is True and self.token:
            sent["X-Rtlab-Token"] = self.token
        elif isinstance(token, str):
            sent["X-Rtlab-Token"] = token
        data = body.encode() if isinstance(body, str) else body
        connection = http.client.HTTPConnection("127.0.0.1", self.port, timeout=timeout)
        try:
            connection.putrequest(method, path, skip_host=host is not True, skip_accept_encoding=True)
            if isinstance(host, str):
                connection.putheader("Host", host)
            for key, value in sent.items():
                connection.putheader(key, value)
            if data is not None:
                connection.putheader("Content-Length", str(len(data)))
            connection.endheaders(data)
            response = connection.getresponse()
            return response.status, response.headers, response.read()
        finally:
            connection.close()

    def get(self, path, **options):
        return self.request("GET", path, **options)

    def post(self, path, body, **options):
        return self.request("POST", path, body, **options)

    def stop(self):
        """Ends the server; what it wrote on stderr."""
        self.process.terminate()
        self.process.wait(30)
        self.errors.seek(0)
        return self.errors.read()
