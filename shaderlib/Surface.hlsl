// Surface.hlsl: what lighting needs to know about the point being shaded (Surface.wgsl's).
#ifndef KILN_SURFACE_INCLUDED
#define KILN_SURFACE_INCLUDED

struct Surface {
    float3 normal;
    // From the surface towards the camera, normalised.
    float3 viewDirection;
    float3 color;
    float alpha;
    float metallic;
    float smoothness;
};

#endif
