!!ARBfp1.0
# state.material bindings, default, front and back faces (ARBfp 3.11.3.2, Table X.2.2)
# Two-sided material: local 0.x < 0 selects the back material.
PARAM amb  = state.material.ambient;
PARAM dif  = state.material.diffuse;
PARAM spe  = state.material.specular;
PARAM emi  = state.material.emission;
PARAM shi  = state.material.shininess;
PARAM fAmb = state.material.front.ambient;
PARAM fDif = state.material.front.diffuse;
PARAM fSpe = state.material.front.specular;
PARAM fEmi = state.material.front.emission;
PARAM fShi = state.material.front.shininess;
PARAM bAmb = state.material.back.ambient;
PARAM bDif = state.material.back.diffuse;
PARAM bSpe = state.material.back.specular;
PARAM bEmi = state.material.back.emission;
PARAM bShi = state.material.back.shininess;
TEMP front, back, c;
MAD front, amb, fDif, emi;
MAD front, dif, fAmb, front;
MAD front, spe, fSpe, front;
ADD front, front, fEmi;
MUL front.a, shi.x, fShi.x;
MAD back, bAmb, bDif, bEmi;
MAD back, bSpe, fragment.color.secondary, back;
MUL back.a, bShi.x, 0.0078125;
CMP c, program.local[0].x, back, front;
MUL result.color, c, fragment.color;
END
