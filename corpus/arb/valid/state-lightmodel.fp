!!ARBfp1.0
# state.lightmodel ambient and front/back scene colours (ARBfp 3.11.3.2, Table X.2.3)
PARAM ambient = state.lightmodel.ambient;
PARAM scene   = state.lightmodel.scenecolor;
PARAM sceneF  = state.lightmodel.front.scenecolor;
PARAM sceneB  = state.lightmodel.back.scenecolor;
TEMP c;
ADD c, scene, sceneF;
MUL c, c, 0.5;
CMP c, program.local[0].x, sceneB, c;
MAD result.color, ambient, fragment.color, c;
END
