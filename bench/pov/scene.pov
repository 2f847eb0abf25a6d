// POV-Ray 3.7 side of the gtrace comparison (bench/pov/bench.sh): checker floor, glass sphere, mirror
// sphere, wood box, marble sphere, two point lights; 800x600, 1 sample per pixel, trace depth 8.
// Coordinates are gtrace's with z negated (POV-Ray is left-handed); `angle` is the horizontal field of
// view equal to gtrace's 40 degrees vertical at 4:3.
// The same picture as scene.scene (bench.sh prints the mean absolute difference per channel): POV-Ray's
// diffuse is albedo * light * cos, without gtrace's (Lambert's) 1/pi, and its fade makes a light's colour at
// distance d colour * 2 / (1 + d^2); so a gtrace point light of intensity I is here a light of colour
// I / (2 pi) (120 -> 19.0986, 60 -> 9.5493), which gives I / (pi d^2) within 2% beyond d = 7 (the lights
// are 8 to 12 units from the objects). bench.sh writes the file with File_Gamma=sRGB, as gtrace does.
// Documented differences that remain: the turbulence of the wood and the marble is POV-Ray's noise, not
// the library's, so the veins and the rings' wobble differ in detail; POV-Ray's shadow through the glass
// is filtered by the pigment only, gtrace's by the Fresnel transmission of both surfaces.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 ambient_light 0 }

camera { location <0, 2.2, -8> look_at <0, 0.8, 0> right x * 4 / 3 angle 51.76 }
light_source { <-5, 8, -6> color rgb 19.0986 fade_distance 1 fade_power 2 }
light_source { <6, 6, -3> color rgb 9.5493 fade_distance 1 fade_power 2 }
background { color rgb <0.25, 0.3, 0.4> }

plane { y, 0
  pigment { checker color rgb 0.8 color rgb 0.1 }
  finish { ambient 0 diffuse 1 }
}
sphere { <-1.6, 1, 0>, 1   // glass: Fresnel reflection and refraction, filtered shadows
  pigment { rgbf <1, 1, 1, 1> }
  finish { ambient 0 diffuse 0 reflection { 0, 1 fresnel on } conserve_energy }
  interior { ior 1.5 }
}
sphere { <1.6, 1, -0.4>, 1 // mirror
  pigment { rgb 0 }
  finish { ambient 0 diffuse 0 reflection 0.9 }
}
box { <-0.6, 0, -2.6>, <0.6, 0.8, -1.6> // wood
  pigment { wood turbulence 0.1 color_map { [0 rgb <0.75, 0.5, 0.25>] [1 rgb <0.4, 0.22, 0.08>] } scale 0.15 }
  finish { ambient 0 diffuse 1 }
}
sphere { <0, 0.7, 1.6>, 0.7 // marble
  pigment { marble turbulence 1 color_map { [0 rgb 0.9] [0.8 rgb <0.5, 0.45, 0.4>] [1 rgb 0.2] } scale 0.5 }
  finish { ambient 0 diffuse 1 }
}
