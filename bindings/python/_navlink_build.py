"""The PEP 517 build backend of the navlink package (pyproject.toml), standard library only.

The wheel holds navlink.py as navlink/__init__.py beside navlink/py.typed: PEP 561 type information ships
in packages, not in single-module distributions, while the source tree keeps the files that its test and
a user with NAVLINK_LIBRARY import directly (navlink.py with the generated raw layer _navlink_abi.py and its
base classes _navlink_structs.py, which go into the package beside it). It also holds
navlink/_built_against.py, the folder of the library pkg-config named when it was built, which the
module tries before looking the library up again.
"""
import base64
import hashlib
import io
import os
import re
import subprocess
import tarfile
import zipfile

HERE = os.path.dirname(os.path.abspath(__file__))
WHEEL_TAG = "py3-none-any"
# Fixed times make the same sources give the same archive bytes.
ZIP_TIME = (1980, 1, 1, 0, 0, 0)
PACKAGE_FILES = {"navlink/__init__.py": "navlink.py", "navlink/_navlink_abi.py": "_navlink_abi.py",
                 "navlink/_navlink_structs.py": "_navlink_structs.py", "navlink/py.typed": "py.typed"}
SDIST_FILES = ["pyproject.toml", "_navlink_build.py", "navlink.py", "_navlink_abi.py", "_navlink_structs.py", "py.typed"]


def _read(name):
    with open(os.path.join(HERE, name), "rb") as f:
        return f.read()


def _project():
    """The [project] table's string values, and the version: the headers' (_navlink_abi.py)."""
    table, project = None, {}
    for line in _read("pyproject.toml").decode().splitlines():
        header = re.match(r"\s*\[([^\]]+)\]", line)
        if header:
            table = header.group(1).strip()
            continue
        pair = re.match(r'\s*([A-Za-z][\w-]*)\s*=\s*"([^"]*)"\s*(#.*)?$', line)
        if table == "project" and pair:
            project[pair.group(1)] = pair.group(2)
    abi = _read("_navlink_abi.py").decode()
    parts = [re.search(r"^VERSION_%s = (\d+)$" % part, abi, flags=re.M) for part in ("MAJOR", "MINOR", "PATCH")]
    if not all(parts):
        raise RuntimeError("_navlink_build: _navlink_abi.py has no VERSION_MAJOR, VERSION_MINOR and VERSION_PATCH lines")
    project["version"] = ".".join(m.group(1) for m in parts)
    return project


def _metadata(project):
    lines = ["Metadata-Version: 2.1", "Name: " + project["name"], "Version: " + project["version"],
             "Summary: " + project["description"], "Requires-Python: " + project["requires-python"],
             "License: " + project["license"]]
    return ("\n".join(lines) + "\n").encode()


def _dist_info(project):
    return "%s-%s.dist-info" % (project["name"], project["version"])


def _record_line(name, data):
    digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
    return "%s,sha256=%s,%d" % (name, digest, len(data))


def _write_wheel(directory, project, files):
    """A wheel of `files` ({name in the wheel: bytes}) and its .dist-info; returns its file name."""
    dist_info = _dist_info(project)
    files = dict(files)
    files[dist_info + "/METADATA"] = _metadata(project)
    files[dist_info + "/WHEEL"] = ("Wheel-Version: 1.0\nGenerator: navlink _navlink_build\nRoot-Is-Purelib: true\n"
                                   "Tag: %s\n" % WHEEL_TAG).encode()
    files[dist_info + "/top_level.txt"] = b"navlink\n"
    record_name = dist_info + "/RECORD"
    record = "".join(_record_line(name, data) + "\n" for name, data in files.items()) + record_name + ",,\n"
    files[record_name] = record.encode()
    wheel_name = "%s-%s-%s.whl" % (project["name"], project["version"], WHEEL_TAG)
    with zipfile.ZipFile(os.path.join(directory, wheel_name), "w", zipfile.ZIP_DEFLATED) as wheel:
        for name, data in files.items():
            entry = zipfile.ZipInfo(name, ZIP_TIME)
            entry.external_attr = 0o644 << 16
            entry.compress_type = zipfile.ZIP_DEFLATED
            wheel.writestr(entry, data)
    return wheel_name


def get_requires_for_build_wheel(config_settings=None):
    return []


def get_requires_for_build_editable(config_settings=None):
    return []


def get_requires_for_build_sdist(config_settings=None):
    return []


def _built_against():
    """navlink/_built_against.py: the folder of the libnavlink pkg-config names at build time (with the
    PKG_CONFIG_PATH the installer set), so the installed package finds that library once the variable
    is gone. None when pkg-config finds no navlink.pc: the module looks the library up at import."""
    try:
        run = subprocess.run(["pkg-config", "--variable=libdir", "navlink"], capture_output=True, text=True, timeout=30)
    except (OSError, subprocess.SubprocessError):
        return None
    libdir = run.stdout.strip()
    if run.returncode != 0 or not libdir:
        return None
    return ("# The folder of the libnavlink this package was built against (pkg-config at pip install time).\n"
            "LIBRARY_DIR = %r\n" % os.path.realpath(libdir)).encode()


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    files = {name: _read(source) for name, source in PACKAGE_FILES.items()}
    built_against = _built_against()
    if built_against is not None:
        files["navlink/_built_against.py"] = built_against
    return _write_wheel(wheel_directory, _project(), files)


def build_editable(wheel_directory, config_settings=None, metadata_directory=None):
    """A wheel whose .pth puts this folder on sys.path: `import navlink` runs navlink.py where it is."""
    return _write_wheel(wheel_directory, _project(), {"navlink.pth": (HERE + "\n").encode()})


def build_sdist(sdist_directory, config_settings=None):
    project = _project()
    base = "%s-%s" % (project["name"], project["version"])
    members = {name: _read(name) for name in SDIST_FILES}
    members["PKG-INFO"] = _metadata(project)
    sdist_name = base + ".tar.gz"
    with tarfile.open(os.path.join(sdist_directory, sdist_name), "w:gz", format=tarfile.PAX_FORMAT) as sdist:
        for name, data in members.items():
            entry = tarfile.TarInfo("%s/%s" % (base, name))
            entry.size, entry.mode = len(data), 0o644
            sdist.addfile(entry, io.BytesIO(data))
    return sdist_name
