// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 7.5: gl_DepthRange, gl_ClipPlane, gl_Point, gl_FrontMaterial, gl_BackMaterial, gl_LightSource, gl_LightModel, gl_FrontLightModelProduct, gl_FrontLightProduct, gl_TextureEnvColor, gl_EyePlaneS..Q, gl_ObjectPlaneS..Q, gl_Fog
void main()
{
    float d = gl_DepthRange.near + gl_DepthRange.far + gl_DepthRange.diff;
    vec4 cp = gl_ClipPlane[gl_MaxClipPlanes - 1];
    float p = gl_Point.size + gl_Point.sizeMin + gl_Point.sizeMax + gl_Point.fadeThresholdSize
            + gl_Point.distanceConstantAttenuation + gl_Point.distanceLinearAttenuation
            + gl_Point.distanceQuadraticAttenuation;
    vec4 m = gl_FrontMaterial.emission + gl_FrontMaterial.ambient + gl_FrontMaterial.diffuse
           + gl_BackMaterial.specular * gl_BackMaterial.shininess;
    vec4 l = gl_LightSource[0].ambient + gl_LightSource[0].diffuse + gl_LightSource[0].specular
           + gl_LightSource[0].position + gl_LightSource[0].halfVector
           + vec4(gl_LightSource[0].spotDirection, gl_LightSource[0].spotExponent)
           * gl_LightSource[0].spotCutoff * gl_LightSource[0].spotCosCutoff
           * gl_LightSource[0].constantAttenuation * gl_LightSource[0].linearAttenuation
           * gl_LightSource[0].quadraticAttenuation;
    vec4 lm = gl_LightModel.ambient + gl_FrontLightModelProduct.sceneColor + gl_BackLightModelProduct.sceneColor;
    vec4 lp = gl_FrontLightProduct[1].ambient + gl_FrontLightProduct[1].diffuse + gl_BackLightProduct[0].specular;
    vec4 te = gl_TextureEnvColor[0] + gl_EyePlaneS[0] + gl_EyePlaneT[0] + gl_EyePlaneR[0] + gl_EyePlaneQ[0]
            + gl_ObjectPlaneS[0] + gl_ObjectPlaneT[0] + gl_ObjectPlaneR[0] + gl_ObjectPlaneQ[0];
    vec4 f = gl_Fog.color * (gl_Fog.density + gl_Fog.start + gl_Fog.end + gl_Fog.scale);
    gl_FragColor = cp + m + l + lm + lp + te + f + vec4(d + p);
}
