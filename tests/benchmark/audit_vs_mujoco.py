"""How many bodies of public MJCF models polymass audit computes as MuJoCo
does: a measurement, never a test (it needs models from PyPI packages).

    python -m venv /tmp/v && /tmp/v/bin/pip install mujoco numpy pybullet gymnasium dm_control
    SP=$(/tmp/v/bin/python -c 'import site; print(site.getsitepackages()[0])')
    /tmp/v/bin/python tests/benchmark/audit_vs_mujoco.py build/dev/src/cli/polymass \
        $SP/pybullet_data $SP/gymnasium/envs/mujoco/assets $SP/dm_control

Over every MJCF file MuJoCo compiles, a body counts when the audit agrees with
MuJoCo within 1e-6 relative (mass; centre of mass against its distance from
the origin or the radius of gyration; inertia tensor against its largest
entry):
  exact  the audit's `computed` against MuJoCo compiling with inertiafromgeom
         forced true and every mesh's inertia exact;
  as_is  over the bodies whose inertial MuJoCo infers from the file as it is
         (`inferred`), the audit's `mujoco_legacy` where it gives one, else
         `computed`, against MuJoCo's compile of the file.
"""

import json
import pathlib
import subprocess
import sys

import mujoco
import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).parents[1] / "cli"))
from mujoco_body import body_inertial


def agree(figure, mass, com, inertia):
    if figure is None:
        return False
    gyration = np.sqrt(max(np.trace(inertia), 1e-300) / max(mass, 1e-300))
    return bool(
        abs(figure["mass"] - mass) <= 1e-6 * mass
        and np.abs(np.array(figure["center_of_mass"]) - com).max()
        <= 1e-6 * max(np.linalg.norm(com), gyration)
        and np.abs(np.array(figure["inertia"]) - inertia).max() <= 1e-6 * np.abs(inertia).max()
    )


def compiled(path):
    """MuJoCo's model of the file as it is, the same with inferred exact
    inertials, and which bodies the file's own compile infers."""
    original = mujoco.MjSpec.from_file(str(path))
    rule = original.compiler.inertiafromgeom
    inferred = [
        rule == mujoco.mjtInertiaFromGeom.mjINERTIAFROMGEOM_TRUE
        or (rule == mujoco.mjtInertiaFromGeom.mjINERTIAFROMGEOM_AUTO and not body.explicitinertial)
        for body in original.bodies
    ]
    spec = mujoco.MjSpec.from_file(str(path))
    spec.compiler.inertiafromgeom = mujoco.mjtInertiaFromGeom.mjINERTIAFROMGEOM_TRUE
    for mesh in spec.meshes:
        mesh.inertia = mujoco.mjtMeshInertia.mjMESH_INERTIA_EXACT
    return mujoco.MjModel.from_xml_path(str(path)), spec.compile(), inferred


def main(exe, roots):
    files = sorted(
        p
        for r in roots
        for p in pathlib.Path(r).rglob("*.xml")
        if "<mujoco" in p.read_text(errors="ignore")
    )
    counts = dict(files=0, bodies=0, exact=0, inferred=0, as_is=0)
    for path in files:
        try:
            as_is, exact, inferred = compiled(path)
        except Exception:  # a file MuJoCo refuses is not counted
            continue
        out = subprocess.run(
            [exe, "audit", "--json", str(path)], capture_output=True, text=True, check=False
        )
        links = json.loads(out.stdout)["links"] if out.stdout.startswith("{") else []
        if len(links) != exact.nbody - 1:
            print(f"{path}: {len(links)} links for {exact.nbody - 1} bodies: not counted")
            continue
        counts["files"] += 1
        for i in range(1, exact.nbody):
            link = links[i - 1]
            counts["bodies"] += 1
            counts["exact"] += agree(link["computed"], *body_inertial(exact, i))
            if inferred[i]:
                counts["inferred"] += 1
                counts["as_is"] += agree(
                    link.get("mujoco_legacy") or link["computed"], *body_inertial(as_is, i)
                )
    print(counts)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2:])
