// ARGS: --vectors 8
// A shader arbiter's checker rejects is not run: its diagnostic, exit 1.
void main()
{
    gl_Position = vec3(1.0);
}
