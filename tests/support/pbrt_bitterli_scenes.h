// Excerpts of three pbrt-v4 scenes from Benedikt Bitterli's rendering resources
// (https://benedikt-bitterli.me/resources/, CC0), as the gonsolo/bitterli collection has them:
// the coffee maker whole, the Cornell box's and Veach's MIS scene's settings, materials and lights.
#pragma once

namespace photon::test {

inline const char* const kCoffeeScene = R"pbrt(Integrator "path"
    "integer maxdepth" [ 17 ]
Transform [ 0.999974 0.000285892 0.00726552 -0 -0 0.999227 -0.0393187 -0 0.00727114 -0.0393177 -0.9992 -0 -0.00306164 -0.165588 0.835307 1  ]
Sampler "sobol"
    "integer pixelsamples" [ 64 ]
PixelFilter "triangle"
    "float xradius" [ 1 ]
    "float yradius" [ 1 ]
Film "rgb"
    "string filename" [ "coffee.exr" ]
    "integer yresolution" [ 1000 ]
    "integer xresolution" [ 800 ]
Camera "perspective"
    "float fov" [ 25 ]


WorldBegin

MakeNamedMaterial "Plastic_Orange"
    "string type" [ "coateddiffuse" ]
    "rgb reflectance" [ 1 0.378676 0.013473 ]
    "float vroughness" [ 0.001 ]
    "float uroughness" [ 0.001 ]
    "bool remaproughness" [ false ]
MakeNamedMaterial "Plastic_Black"
    "string type" [ "coateddiffuse" ]
    "bool remaproughness" [ false ]
    "float vroughness" [ 0.1 ]
    "float uroughness" [ 0.1 ]
    "rgb reflectance" [ 0.00631 0.00631 0.00631 ]
MakeNamedMaterial "Glass"
    "string type" [ "dielectric" ]
    "float eta" [ 1.5 ]
    "bool remaproughness" [ false ]
MakeNamedMaterial "Metal"
    "string type" [ "conductor" ]
    "float roughness" [ 0 ]
    "spectrum eta" [ "metal-Ag-eta" ]
    "spectrum k" [ "metal-Ag-k" ]
MakeNamedMaterial "Floor"
    "string type" [ "coateddiffuse" ]
    "rgb reflectance" [ 0.578596 0.578596 0.578596 ]
    "float vroughness" [ 0.001 ]
    "float uroughness" [ 0.001 ]
    "bool remaproughness" [ false ]
NamedMaterial "Plastic_Black"
Shape "plymesh"
    "string filename" [ "models/Mesh013.ply" ]
Shape "plymesh"
    "string filename" [ "models/Mesh008.ply" ]
NamedMaterial "Glass"
Shape "plymesh"
    "string filename" [ "models/Mesh010.ply" ]
NamedMaterial "Plastic_Orange"
Shape "plymesh"
    "string filename" [ "models/Mesh009.ply" ]
NamedMaterial "Metal"
Shape "plymesh"
    "string filename" [ "models/Mesh015.ply" ]
NamedMaterial "Plastic_Orange"
Shape "plymesh"
    "string filename" [ "models/Mesh012.ply" ]
Shape "plymesh"
    "string filename" [ "models/Mesh016.ply" ]
NamedMaterial "Plastic_Black"
Shape "plymesh"
    "string filename" [ "models/Mesh017.ply" ]
Shape "plymesh"
    "string filename" [ "models/Mesh018.ply" ]
Shape "plymesh"
    "string filename" [ "models/Mesh019.ply" ]
Shape "plymesh"
    "string filename" [ "models/Mesh007.ply" ]
NamedMaterial "Plastic_Orange"
Shape "plymesh"
    "string filename" [ "models/Mesh006.ply" ]
NamedMaterial "Plastic_Black"
Shape "plymesh"
    "string filename" [ "models/Mesh005.ply" ]
Shape "plymesh"
    "string filename" [ "models/Mesh003.ply" ]
NamedMaterial "Metal"
Shape "plymesh"
    "string filename" [ "models/Mesh002.ply" ]
NamedMaterial "Plastic_Orange"
Shape "plymesh"
    "string filename" [ "models/Mesh001.ply" ]
NamedMaterial "Plastic_Black"
Shape "plymesh"
    "string filename" [ "models/Mesh011.ply" ]
NamedMaterial "Plastic_Orange"
Shape "plymesh"
    "string filename" [ "models/Mesh000.ply" ]
NamedMaterial "Plastic_Black"
Shape "plymesh"
    "string filename" [ "models/Mesh014.ply" ]
NamedMaterial "Floor"
Shape "plymesh"
    "string filename" [ "models/Mesh004.ply" ]

AttributeBegin
    AreaLightSource "diffuse"
        "rgb L" [ 2 2 2 ]
    Material "diffuse"
        "rgb reflectance" [ 0 0 0 ]
    Shape "trianglemesh"
        "point2 uv" [ 0 0 1 0 1 1 0 1 
            ]
        "normal N" [ 0.906308 -2.5889e-7 -0.422619 0.906308 -2.5889e-7 -0.422619 
                     0.906308 -2.5889e-7 -0.422619 0.906308 -2.5889e-7 -0.422619 ]
        "point3 P" [ -0.359309 0.449693 -0.010809 -0.196537 0.449693 0.338256 -0.196537 
                     0.000849009 0.338256 -0.359309 0.000848979 -0.010809 ]
        "integer indices" [ 0 1 2 0 2 3 ]
AttributeEnd

AttributeBegin
    AreaLightSource "diffuse"
        "rgb L" [ 2 2 2 ]
    Material "diffuse"
        "rgb reflectance" [ 0 0 0 ]
    Shape "trianglemesh"
        "point2 uv" [ 0 0 1 0 1 1 0 1 
            ]
        "normal N" [ -0.999923 -4.37114e-8 -0.0124461 -0.999923 -4.37114e-8 -0.0124461 
                     -0.999923 -4.37114e-8 -0.0124461 -0.999923 -4.37114e-8 -0.0124461 ]
        "point3 P" [ 0.320673 0.027337 0.228975 0.320673 0.476182 0.228975 0.325221 
                     0.476182 -0.136419 0.325221 0.027337 -0.136419 ]
        "integer indices" [ 0 1 2 0 2 3 ]
AttributeEnd

AttributeBegin
    AreaLightSource "diffuse"
        "rgb L" [ 2 2 2 ]
    Material "diffuse"
        "rgb reflectance" [ 0 0 0 ]
    Shape "trianglemesh"
        "point2 uv" [ 0 0 1 0 1 1 0 1 
            ]
        "normal N" [ 1.50996e-7 -1 -1.89944e-7 1.50996e-7 -1 -1.89944e-7 1.50996e-7 
                     -1 -1.89944e-7 1.50996e-7 -1 -1.89944e-7 ]
        "point3 P" [ 0.230128 0.50385 0.267372 -0.230128 0.50385 0.267372 -0.230128 
                     0.50385 -0.192885 0.230128 0.50385 -0.192885 ]
        "integer indices" [ 0 1 2 0 2 3 ]
AttributeEnd
)pbrt";

inline const char* const kCornellBoxExcerpt = R"pbrt(Integrator "path" "integer maxdepth" [ 4 ] # gonsolo 65
Transform [ 1 -0 -0 -0 -0 1 -0 -0 -0 -0 -1 -0 -0 -1 6.8 1  ]
Sampler "sobol" "integer pixelsamples" [ 1 ] # gonsolo 512

#PixelFilter "triangle" "float xradius" [ 1 ] "float yradius" [ 1 ]
#PixelFilter "box" "float xradius" [ 1 ] "float yradius" [ 1 ]
PixelFilter "gaussian" "float xradius" [ 1.5 ] "float yradius" [ 1.5 ]

# gonsolo
Accelerator "bvh"
#Accelerator "embree"
#Accelerator "optix"

Film "rgb"
    "string filename" [ "cornell-box.exr" ]
    #"integer yresolution" [ 32 ] "integer xresolution" [ 32 ]
    "integer yresolution" [ 64 ]  "integer xresolution" [ 64 ]
    #"integer yresolution" [ 128 ] "integer xresolution" [ 128 ]
    #"integer yresolution" [ 256 ] "integer xresolution" [ 256 ]
    #"integer yresolution" [ 512 ] "integer xresolution" [ 512 ]
    #"integer yresolution" [ 1024 ] "integer xresolution" [ 1024 ]
    #"integer xresolution" [ 1920 ] "integer yresolution" [ 1080 ]
 
Camera "perspective" "float fov" [ 19.5 ]
#Camera "perspective" "float fov" [ 40 ]

WorldBegin

MakeNamedMaterial "LeftWall"
    "string type" [ "diffuse" ]
    "rgb reflectance" [ 0.63 0.065 0.05 ]
MakeNamedMaterial "RightWall"
    "string type" [ "diffuse" ]
    "rgb reflectance" [ 0.14 0.45 0.091 ]
MakeNamedMaterial "Floor"
    "string type" [ "diffuse" ]
    "rgb reflectance" [ 0.725 0.71 0.68 ]
MakeNamedMaterial "Ceiling"
    "string type" [ "diffuse" ]
    "rgb reflectance" [ 0.725 0.71 0.68 ]
MakeNamedMaterial "BackWall"
    "string type" [ "diffuse" ]
    "rgb reflectance" [ 0.725 0.71 0.68 ]
MakeNamedMaterial "ShortBox"
    "string type" [ "diffuse" ]
    "rgb reflectance" [ 0.725 0.71 0.68 ]
MakeNamedMaterial "TallBox"
    "string type" [ "diffuse" ]
    "rgb reflectance" [ 0.725 0.71 0.68 ]
MakeNamedMaterial "Light"
    "string type" [ "diffuse" ]
    "rgb reflectance" [ 0 0 0 ]
NamedMaterial "Floor"
Shape "trianglemesh"
    "point2 uv" [ 0 0 1 0 1 1 0 1 
        ]
    "normal N" [ 4.37114e-8 1 1.91069e-15 4.37114e-8 1 1.91069e-15 4.37114e-8 1 1.91069e-15 
                 4.37114e-8 1 1.91069e-15 ]
    "point3 P" [ -1 1.74846e-7 -1 -1 1.74846e-7 1 1 -1.74846e-7 1 1 -1.74846e-7 -1 ]
    "integer indices" [ 0 1 2 0 2 3 ]
# ... (the other walls and the boxes)

AttributeBegin
    AreaLightSource "diffuse"
        "rgb L" [ 17 12 4 ]
    NamedMaterial "Light"
    Shape "trianglemesh"
        "point2 uv" [ 0 0 1 0 1 1 0 1 
            ]
        "normal N" [ -8.74228e-8 -1 1.86006e-7 -8.74228e-8 -1 1.86006e-7 -8.74228e-8 
                     -1 1.86006e-7 -8.74228e-8 -1 1.86006e-7 ]
        "point3 P" [ -0.24 1.98 -0.22 0.23 1.98 -0.22 0.23 1.98 0.16 -0.24 1.98 0.16 ]
        "integer indices" [ 0 1 2 0 2 3 ]
AttributeEnd
)pbrt";

inline const char* const kVeachMisExcerpt = R"pbrt(Integrator "path"
    "integer maxdepth" [ 3 ]
Transform [ 4.37113e-8 -0 -1 -0 -0 1 -0 -0 -1 -0 -4.37113e-8 -0 -0 -3.5 28.2792 1  ]
Sampler "sobol"
    "integer pixelsamples" [ 1 ] # gonsolo
PixelFilter "triangle"
    "float xradius" [ 1 ]
    "float yradius" [ 1 ]
Film "rgb"
    "string filename" [ "veach-mis.exr" ]
    "integer yresolution" [ 720 ]
    "integer xresolution" [ 1280 ]
Camera "perspective"
    "float fov" [ 20.114292 ]


WorldBegin

MakeNamedMaterial "Diffuse"
    "string type" [ "diffuse" ]
    "rgb reflectance" [ 0.5 0.5 0.5 ]
MakeNamedMaterial "Smooth"
    "string type" [ "conductor" ]
    "float vroughness" [ 0.01 ]
    "float uroughness" [ 0.01 ]
    "bool remaproughness" [ false ]
    "rgb k" [ 3.912949 2.452848 2.142188 ]
    "rgb eta" [ 0.200438 0.924033 1.102212 ]
MakeNamedMaterial "Glossy"
    "string type" [ "conductor" ]
    "float vroughness" [ 0.05 ]
    "float uroughness" [ 0.05 ]
    "bool remaproughness" [ false ]
    "rgb k" [ 3.912949 2.452848 2.142188 ]
    "rgb eta" [ 0.200438 0.924033 1.102212 ]
MakeNamedMaterial "Rough"
    "string type" [ "conductor" ]
    "float vroughness" [ 0.1 ]
    "float uroughness" [ 0.1 ]
    "bool remaproughness" [ false ]
    "rgb k" [ 3.912949 2.452848 2.142188 ]
    "rgb eta" [ 0.200438 0.924033 1.102212 ]
MakeNamedMaterial "Null"
    "string type" [ "diffuse" ]
    "rgb reflectance" [ 0 0 0 ]
MakeNamedMaterial "SuperRough"
    "string type" [ "conductor" ]
    "float vroughness" [ 0.25 ]
    "float uroughness" [ 0.25 ]
    "bool remaproughness" [ false ]
    "rgb k" [ 3.912949 2.452848 2.142188 ]
    "rgb eta" [ 0.200438 0.924033 1.102212 ]
# ... (the four plates)

AttributeBegin
    AreaLightSource "diffuse"
        "rgb L" [ 7.599088 7.599088 7.599088 ]
    NamedMaterial "Null"
    AttributeBegin
        Transform [ 1 0 0 0 0 1 0 0 0 0 1 0 0 6.5 -2.8 1  ]
        Shape "sphere"
            "float radius" [ 1 ]
    AttributeEnd
AttributeEnd

AttributeBegin
    AreaLightSource "diffuse"
        "rgb L" [ 30.396353 30.396353 30.396353 ]
    NamedMaterial "Null"
    AttributeBegin
        Transform [ 1 0 0 0 0 1 0 0 0 0 1 0 0 6.5 0 1  ]
        Shape "sphere"
            "float radius" [ 0.5 ]
    AttributeEnd
AttributeEnd
)pbrt";

}  // namespace photon::test
