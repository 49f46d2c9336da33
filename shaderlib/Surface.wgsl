// Surface.wgsl: what lighting needs to know about the point being shaded.
#ifndef KILN_SURFACE_INCLUDED
#define KILN_SURFACE_INCLUDED

struct Surface {
    normal: vec3<f32>,
    // From the surface towards the camera, normalised.
    viewDirection: vec3<f32>,
    color: vec3<f32>,
    alpha: f32,
    metallic: f32,
    smoothness: f32,
}

#endif
