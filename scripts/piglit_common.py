"""piglit_common: what scripts/piglit-compare and scripts/piglit-parser-compare share: Debian's
piglit package (0~git20220119) unpacked under a work directory, the library piglit's binaries
link (libwaffle-1-0), the environment they run in and the result line they print.
"""
import glob
import os
import re
import subprocess


def unpack(work):
    """Returns piglit's root under WORK, downloading and unpacking the package the first time."""
    root = os.path.join(work, "x", "usr", "lib", "x86_64-linux-gnu", "piglit")
    if os.path.isdir(root):
        return root
    os.makedirs(work, exist_ok=True)
    subprocess.run(["apt-get", "download", "piglit"], cwd=work, check=True)
    deb = glob.glob(os.path.join(work, "piglit_*.deb"))[0]
    subprocess.run(["dpkg-deb", "-x", deb, os.path.join(work, "x")], check=True)
    return root


def install_waffle():
    """Installs libwaffle-1-0, which piglit's shader_runner and glslparsertest link."""
    subprocess.run(["apt-get", "install", "-y", "-qq", "--no-install-recommends",
                    "libwaffle-1-0"], check=True, stdout=subprocess.DEVNULL)


def piglit_env(root, driver):
    """The environment piglit's binaries run in: surfaceless EGL on the given Gallium driver."""
    return dict(os.environ, LD_LIBRARY_PATH=os.path.join(root, "lib"),
                PIGLIT_PLATFORM="surfaceless_egl", PIGLIT_SOURCE_DIR=root,
                GALLIUM_DRIVER=driver)


def piglit_result(stdout):
    """The last `PIGLIT: {"result": ...}` of a piglit binary's output, or None."""
    m = re.findall(r'"result": "(\w+)"', stdout)
    return m[-1] if m else None
