"""Peak mouth area of the net of examples/net_deploy.yaml against the bullets' launch angle.

Usage: /usr/bin/python3 examples/python/launch_angle_study.py [END_TIME]  (s, default 1.2)"""
import pathlib, sys, tempfile
import ancfnet

end_time = sys.argv[1] if len(sys.argv) > 1 else "1.2"
base = (pathlib.Path(__file__).parents[1] / "net_deploy.yaml").read_text()
base = base.replace("end_time: 1.2", f"end_time: {end_time}")
with tempfile.TemporaryDirectory() as out:
    for angle in range(15, 50, 5):
        scene = ancfnet.parse_scene(base.replace("angle: 30", f"angle: {angle}"), f"{angle} deg")
        ancfnet.run(scene, f"{out}/{angle}")
        probes = ancfnet.read_probes(f"{out}/{angle}/probes.csv")
        peak = probes["mouth.area"].argmax()
        print(f"{angle:2d} deg: peak mouth area {probes['mouth.area'][peak]:6.2f} m²"
              f" at t = {probes['time'][peak]:.2f} s")
