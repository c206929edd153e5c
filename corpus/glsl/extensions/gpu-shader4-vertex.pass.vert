// [config]
// expect_result: pass
// glsl_version: 1.10
// require_extensions: GL_EXT_gpu_shader4
// [end config]
// EXT_gpu_shader4: "int gl_VertexID", "int gl_InstanceID" (vertex shaders), integer attributes, "noperspective varying"
#extension GL_EXT_gpu_shader4 : enable
attribute ivec4 bones;
noperspective varying float depth;
flat varying int id;
void main()
{
    id = gl_VertexID + gl_InstanceID + bones.x;
    depth = float(id >> 1);
    gl_Position = ftransform();
}
