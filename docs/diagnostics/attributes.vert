#version 110
// gl_Vertex and five mat4 attributes (four locations each) take 21 of the 16 locations.
attribute mat4 a, b, c, d, e;
void main()
{
    gl_Position = (a * b * c * d * e) * gl_Vertex;
}
