# DEM8 impact case (Dosta et al. 2024, ../shared/dem8/README.md, case 3) in Yade 2023.02a (Debian
# package `yade`). Written for veridem from the README's parameters; run by run_impact.sh as
#   yade -j 1 -n -x impact_yade.py WORKDIR STEPS OUT.csv [ZBALL VZ T0 SKIN]
# WORKDIR holds convert_impact.py's spheres.txt (`x y z radius type`, the ball last) and
# triangles.txt (nine columns a line).
#   law      Ip2_FrictMat_FrictMat_MindlinPhys + Law2_ScGeom_MindlinPhys_Mindlin: Hertz normal force
#            kno delta^1.5, kno = 4/3 E* sqrt(R*); Mindlin no-slip tangential stiffness
#            ks = 8 G* sqrt(R* delta); Coulomb cap; no rolling resistance. Restitution per pair
#            (en MatchMaker: M1-M1 0.5, M1-steel 0.4, steel-steel 0.6) which Yade turns into the
#            damping ratio betan (Thornton et al. 2013 fit) with cn = 2 betan sqrt(m* kn),
#            kn = 3/2 kno sqrt(delta) (see README.md for how this differs from LIGGGHTS'); friction
#            per pair (frictAngle MatchMaker: M1-M1 0.3, M1-steel 0.2, steel-steel 0.5)
#   walls    the box's triangles as fixed steel facets (Ig2_Facet_Sphere_ScGeom, hertzian=True: the
#            sphere's own radius is R* of a sphere-wall contact, as for a flat wall)
#   ball     steel, radius 10 mm, centre z = ZBALL (default 0.06 m), velocity (0, 0, VZ) (default
#            -5 m/s); T0 (default 0 s) is added to the recorded time (run_impact.sh --skip-flight)
#   step     dt = 5e-7 s fixed; InsertionSortCollider with verletDist SKIN (default 2e-4 m, the
#            LIGGGHTS deck's skin); gravity 9.8 m/s^2 along -z; NewtonIntegrator damping 0
# Writes OUT.csv: t [s], z [m] of the ball every 1000 steps (0.5 ms) and at the end; prints the
# wall and CPU time after each chunk, and at the end one line "yade wall S cpu C steps N
# particles P rate R per-cpu-second Q" (the timed runs only; R, Q in particle-steps/s).
import math
import sys
import time

workdir, steps, out_path = sys.argv[1], int(sys.argv[2]), sys.argv[3]
extra = [float(v) for v in sys.argv[4:8]]
ball_z, ball_vz, t0, skin = (extra + [0.06, -5.0, 0.0, 2e-4][len(extra):])[:4]
every = 1000  # steps: 0.5 ms at dt 5e-7 s

steel = O.materials.append(FrictMat(young=210e9, poisson=0.2, density=7200, frictionAngle=math.atan(0.2), label='steel'))
m1 = O.materials.append(FrictMat(young=1.0e9, poisson=0.2, density=2500, frictionAngle=math.atan(0.3), label='M1'))
restitution = MatchMaker(matches=((m1, m1, 0.5), (m1, steel, 0.4), (steel, steel, 0.6)))
friction = MatchMaker(matches=((m1, m1, math.atan(0.3)), (m1, steel, math.atan(0.2)), (steel, steel, math.atan(0.5))))

for line in open(workdir + '/triangles.txt'):
    v = [float(x) for x in line.split()]
    O.bodies.append(facet([Vector3(*v[0:3]), Vector3(*v[3:6]), Vector3(*v[6:9])], material=steel, fixed=True))
ball = None
count = 0
for line in open(workdir + '/spheres.txt'):
    x, y, z, r, kind = line.split()
    body = sphere((float(x), float(y), float(z)), float(r), material=(m1 if kind == '1' else steel))
    ball = O.bodies.append(body)
    count += 1
ball_body = O.bodies[ball]
ball_body.state.pos = Vector3(ball_body.state.pos[0], ball_body.state.pos[1], ball_z)
ball_body.state.vel = Vector3(0, 0, ball_vz)

O.dt = 5e-7
O.dynDt = False
O.engines = [
        ForceResetter(),
        InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Facet_Aabb()], verletDist=skin),
        InteractionLoop(
                [Ig2_Sphere_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom(hertzian=True)],
                [Ip2_FrictMat_FrictMat_MindlinPhys(en=restitution, frictAngle=friction)],
                [Law2_ScGeom_MindlinPhys_Mindlin()],
        ),
        NewtonIntegrator(damping=0, gravity=(0, 0, -9.8)),
]
# The run goes in chunks of `every` steps, recording between them (where O.iter and the bodies'
# positions agree; a PyRunner fires inside a step, after the bodies have moved to the next one).

out = open(out_path, 'w')
out.write('t,z\n')


def record():
    out.write('%.9g,%.12g\n' % (t0 + O.iter * O.dt, O.bodies[ball].state.pos[2]))
    out.flush()


record()
start, cpu_start = time.time(), time.process_time()
while O.iter < steps:
    O.run(min(every, steps - O.iter), True)
    record()
    print('yade step %d t %.6g wall %.2f cpu %.2f' % (O.iter, t0 + O.iter * O.dt, time.time() - start,
                                                     time.process_time() - cpu_start), flush=True)
wall, cpu = time.time() - start, time.process_time() - cpu_start
out.close()
print('yade wall %.3f cpu %.3f steps %d particles %d rate %.4g per-cpu-second %.4g' %
      (wall, cpu, steps, count, count * steps / wall, count * steps / cpu))
