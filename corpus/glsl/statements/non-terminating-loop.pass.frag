// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 6.3: "Non-terminating loops are allowed. The consequences of very long or non-terminating loops are platform dependent."
#version 110
uniform bool spin;
void main()
{
    gl_FragColor = vec4(1.0);
    if (spin)
        while (true)
            ;
}
