// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.1.9 "Variables of the same type can be aggregated into arrays by declaring a name followed by brackets ( [ ] ) enclosing an optional size."
// 4.1.9 "float frequencies[3]; uniform vec4 lightPosition[4]; const int numLights = 2; light lights[numLights];"
#version 110
struct light {
    float intensity;
    vec3 position;
};
float frequencies[3];
uniform vec4 lightPosition[4];
const int numLights = 2;
light lights[numLights];
void main()
{
    float a, b[2], c[3];
    frequencies[2] = 1.0;
    lights[1].intensity = frequencies[2];
    b[1] = c[2] = a = lights[1].intensity;
    gl_Position = lightPosition[3] * b[1];
}
