"""Build hook: puts the tracker's command-line jar (built by Maven) into the wheel and the sdist.

The jar is target/Contact_Tracker-*-cli.jar of the repository (build it first with `mvn -B package -DskipTests`
in the repository's root), or, when building a wheel from an sdist, the jar the sdist carries.
"""
from pathlib import Path

from hatchling.builders.hooks.plugin.interface import BuildHookInterface

JAR = "contact_tracker/contact-tracker.jar"


class JarHook(BuildHookInterface):
    def initialize(self, version, build_data):
        root = Path(self.root)
        carried = root / "src" / JAR
        if carried.is_file():
            jar = carried
        else:
            jars = sorted((root.parent / "target").glob("Contact_Tracker-*-cli.jar"), key=lambda p: p.stat().st_mtime)
            if not jars:
                raise RuntimeError(f"no {root.parent / 'target'}/Contact_Tracker-*-cli.jar: build the jar first "
                                   "(mvn -B package -DskipTests in the repository's root)")
            jar = jars[-1]
        build_data["force_include"][str(jar)] = ("src/" + JAR) if self.target_name == "sdist" else JAR
