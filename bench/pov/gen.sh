#!/bin/sh
# gen.sh DIR - writes bench-pov's generated scenes into DIR (under the build directory; never committed), each as
# the same picture for gtrace and POV-Ray (coordinates with z negated, lights and diffuse converted as in
# scene.pov), 800x600, 1 sample per pixel:
#   spheres.scene / spheres.pov  a grid of 100 x 100 = 10,000 spheres (radius 0.08, spacing 0.2) on a checker
#                                floor, every fifth a mirror, the rest diffuse in two colours; one point light;
#   mesh.obj, mesh.scene /       a bumpy torus of 1000 x 500 quads split in two: 1,000,000 triangles and
#   mesh.inc, mesh.pov           500,000 vertices (OBJ for gtrace, mesh2 for POV-Ray), flat-shaded, diffuse;
#   load.scene, load_mats.scene  the load check: 200,000 named spheres, each naming one of 1,000 named diffuse
#                                materials, rendered at 1x1 (parse and build only; gtrace).
# A file is rewritten only when it is missing or older than this script.
DIR=${1:?usage: gen.sh DIR}
SELF="$0"
mkdir -p "$DIR" || exit 1
stale() { [ ! -s "$DIR/$1" ] || [ "$SELF" -nt "$DIR/$1" ]; }

# POV-Ray's header: camera, light and background equal to gtrace's (scene.pov explains the conversions)
pov_head() { # FROM_Y FROM_Z(gtrace) AT_Y
    cat <<POV
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 ambient_light 0 }
camera { location <0, $1, -$2> look_at <0, $3, 0> right x * 4 / 3 angle 51.76 }
light_source { <-5, 8, -6> color rgb 19.0986 fade_distance 1 fade_power 2 }
background { color rgb <0.25, 0.3, 0.4> }
POV
}
gt_head() { # FROM_Y FROM_Z AT_Y
    cat <<SCENE
colormodel rgb
camera pinhole { from <0, $1, $2> at <0, $3, 0> fov 40 width 800 height 600 spp 1 depth 8 cutoff 0.0039 }
light point { position <-5, 8, 6> intensity rgb 120 120 120 }
light background { color rgb 0.25 0.3 0.4 }
SCENE
}

if stale spheres.scene || stale spheres.pov; then
    { gt_head 6 9 0
      echo 'material floor interpolate { a lambert { reflectance rgb 0.8 0.8 0.8 } b lambert { reflectance rgb 0.1 0.1 0.1 } t checker { dims 2 frequency 1 } }'
      echo 'material red lambert { reflectance rgb 0.7 0.2 0.1 }'
      echo 'material blue lambert { reflectance rgb 0.1 0.3 0.7 }'
      echo 'material chrome mirror { reflectance rgb 0.9 0.9 0.9 }'
      echo 'object plane { point <0, 0, 0> normal <0, 1, 0> material floor }'
    } > "$DIR/spheres.scene"
    { pov_head 6 9 0
      echo 'plane { y, 0 pigment { checker color rgb 0.8 color rgb 0.1 } finish { ambient 0 diffuse 1 } }'
      echo '#declare Red = texture { pigment { rgb <0.7, 0.2, 0.1> } finish { ambient 0 diffuse 1 } }'
      echo '#declare Blue = texture { pigment { rgb <0.1, 0.3, 0.7> } finish { ambient 0 diffuse 1 } }'
      echo '#declare Chrome = texture { pigment { rgb 0 } finish { ambient 0 diffuse 0 reflection 0.9 } }'
    } > "$DIR/spheres.pov"
    awk -v gt="$DIR/spheres.scene" -v pov="$DIR/spheres.pov" 'BEGIN {
        for (i = 0; i < 100; i++)
            for (j = 0; j < 100; j++) {
                k = i * 100 + j
                x = (i - 49.5) * 0.2; z = (j - 49.5) * 0.2
                if (k % 5 == 0) { m = "chrome"; t = "Chrome" } else if (k % 2) { m = "red"; t = "Red" } else { m = "blue"; t = "Blue" }
                printf "object sphere { center <%.2f, 0.08, %.2f> radius 0.08 material %s }\n", x, z, m >> gt
                printf "sphere { <%.2f, 0.08, %.2f>, 0.08 texture { %s } }\n", x, -z, t >> pov
            }
    }'
fi

if stale mesh.obj || stale mesh.inc; then
    # torus: major radius 1.5 around y, minor radius 0.6 with bumps; vertex (i, j) at u = i / 1000, v = j / 500
    awk -v obj="$DIR/mesh.obj" -v inc="$DIR/mesh.inc" 'BEGIN {
        NU = 1000; NV = 500; pi = 3.14159265358979
        print "# bench-pov: bumpy torus, " NU * NV " vertices, " 2 * NU * NV " triangles" > obj
        printf "mesh2 {\n  vertex_vectors { %d,\n", NU * NV > inc
        for (i = 0; i < NU; i++) {
            u = 2 * pi * i / NU
            for (j = 0; j < NV; j++) {
                v = 2 * pi * j / NV
                r = 0.6 * (1 + 0.12 * sin(24 * u) * sin(10 * v))
                x = (1.5 + r * cos(v)) * cos(u); y = r * sin(v) + 0.9; z = (1.5 + r * cos(v)) * sin(u)
                printf "v %.5f %.5f %.5f\n", x, y, z > obj
                printf "    <%.5f, %.5f, %.5f>,\n", x, y, -z > inc
            }
        }
        printf "  }\n  face_indices { %d,\n", 2 * NU * NV > inc
        for (i = 0; i < NU; i++) {
            i1 = (i + 1) % NU
            for (j = 0; j < NV; j++) {
                j1 = (j + 1) % NV
                a = i * NV + j; b = i1 * NV + j; c = i1 * NV + j1; d = i * NV + j1
                printf "f %d %d %d\nf %d %d %d\n", a + 1, b + 1, c + 1, a + 1, c + 1, d + 1 > obj
                printf "    <%d, %d, %d>, <%d, %d, %d>,\n", a, b, c, a, c, d > inc
            }
        }
        print "  }\n  texture { pigment { rgb <0.7, 0.5, 0.3> } finish { ambient 0 diffuse 1 } }\n}" > inc
    }'
    { gt_head 4.5 6 0.6
      echo 'material clay lambert { reflectance rgb 0.7 0.5 0.3 }'
      echo 'material floor lambert { reflectance rgb 0.5 0.5 0.5 }'
      echo 'object plane { point <0, 0, 0> normal <0, 1, 0> material floor }'
      echo 'object mesh { file "mesh.obj" material clay }'
    } > "$DIR/mesh.scene"
    { pov_head 4.5 6 0.6
      echo 'plane { y, 0 pigment { rgb 0.5 } finish { ambient 0 diffuse 1 } }'
      echo '#include "mesh.inc"'
    } > "$DIR/mesh.pov"
fi

if stale load.scene || stale load_mats.scene; then
    awk -v mats="$DIR/load_mats.scene" 'BEGIN {
        print "include \"load_mats.scene\""
        print "camera pinhole { from <0, 0, -10> at <0, 0, 0> width 1 height 1 spp 1 depth 1 }"
        print "light point { position <0, 10, -10> intensity rgb 10 10 10 }"
        for (i = 0; i < 1000; i++)
            printf "material m%d lambert { reflectance rgb 0.5 0.5 0.5 }\n", i > mats
        for (i = 0; i < 200000; i++)
            printf "object o%d sphere { center <%d, %d, %d> radius 0.3 material m%d }\n", i, i % 100, int(i / 100) % 100, int(i / 10000), i % 1000
    }' > "$DIR/load.scene"
fi
