<?xml version='1.0' encoding='utf-8'?>
<!DOCTYPE TS>
<TS version="2.1" language="es_ES">
    <context>
        <name>CalibrationWizard</name>
        <message>
            <source>Hoang's accuracy pattern (10 lines of 40 mm) does not fit in this machine's safe area.</source>
            <translation>El patrón de precisión de Hoang (10 líneas de 40 mm) no cabe en el área segura de esta máquina.</translation>
        </message>
        <message>
            <source>The simulated machine drew %1 lines instead of %2.</source>
            <translation>La máquina simulada dibujó %1 líneas en lugar de %2.</translation>
        </message>
        <message>
            <source>A simulated line is too short to measure.</source>
            <translation>Una línea simulada es demasiado corta para medirla.</translation>
        </message>
    </context>
    <context>
        <name>Design</name>
        <message>
            <source>%1 must be a positive length in mm</source>
            <translation>%1 debe ser una longitud positiva en mm</translation>
        </message>
        <message>
            <source>the rectangle's width</source>
            <translation>el ancho del rectángulo</translation>
        </message>
        <message>
            <source>the rectangle's height</source>
            <translation>el alto del rectángulo</translation>
        </message>
        <message>
            <source>the shortest link</source>
            <translation>el brazo más corto</translation>
        </message>
        <message>
            <source>the longest link</source>
            <translation>el brazo más largo</translation>
        </message>
        <message>
            <source>the shortest link (%1 mm) is longer than the longest (%2 mm)</source>
            <translation>el brazo más corto (%1 mm) es más largo que el más largo (%2 mm)</translation>
        </message>
        <message>
            <source>the motor spacing must be 0 mm or more</source>
            <translation>la separación entre motores debe ser de 0 mm o más</translation>
        </message>
        <message>
            <source>the smallest motor spacing (%1 mm) exceeds the largest (%2 mm)</source>
            <translation>la menor separación entre motores (%1 mm) supera la mayor (%2 mm)</translation>
        </message>
        <message>
            <source>the clearance must be 0 mm or more</source>
            <translation>la holgura debe ser de 0 mm o más</translation>
        </message>
        <message>
            <source>the type II margin must be from 0 to below 90 deg</source>
            <translation>el margen de tipo II debe estar entre 0 y menos de 90°</translation>
        </message>
        <message>
            <source>mix weights must be finite and not negative</source>
            <translation>los pesos de la mezcla deben ser finitos y no negativos</translation>
        </message>
        <message>
            <source>mix weights must not all be zero</source>
            <translation>los pesos de la mezcla no pueden ser todos cero</translation>
        </message>
    </context>
    <context>
        <name>DesignPainter</name>
        <message>
            <source>Workspace, singularity-free region and type II curves</source>
            <translation>Espacio de trabajo, zona sin singularidades y curvas de tipo II</translation>
        </message>
        <message>
            <source>a1 = %1, b1 = %2, a2 = %3, b2 = %4, w = %5 mm, working mode %6</source>
            <translation>a1 = %1, b1 = %2, a2 = %3, b2 = %4, w = %5 mm, modo de trabajo %6</translation>
        </message>
        <message>
            <source>Rectangle x %1 .. %2, y %3 .. %4 mm; worst condition number %5 (mean %6)</source>
            <translation>Rectángulo x %1 .. %2, y %3 .. %4 mm; peor número de condición %5 (media %6)</translation>
        </message>
        <message>
            <source>Type II margin %1 deg, type I margin %2 deg, footprint %3 cm²</source>
            <translation>Margen tipo II %1°, margen tipo I %2°, superficie ocupada %3 cm²</translation>
        </message>
        <message>
            <source>Worst %1 um per step, worst motor speed %2 deg/s</source>
            <translation>Peor %1 µm por paso, peor velocidad de motor %2°/s</translation>
        </message>
    </context>
    <context>
        <name>DocumentCommands</name>
        <message>
            <source>Import drawing</source>
            <translation>Importar dibujo</translation>
        </message>
        <message>
            <source>Move drawing</source>
            <translation>Mover dibujo</translation>
        </message>
        <message>
            <source>Change working mode</source>
            <translation>Cambiar modo de trabajo</translation>
        </message>
        <message>
            <source>Change machine profile</source>
            <translation>Cambiar perfil de máquina</translation>
        </message>
        <message>
            <source>Rotate drawing</source>
            <translation>Girar el dibujo</translation>
        </message>
        <message>
            <source>Resize drawing</source>
            <translation>Cambiar el tamaño del dibujo</translation>
        </message>
    </context>
    <context>
        <name>ImportError</name>
        <message>
            <source>%1 has a point at (%2, %3) mm, beyond the %4 mm limit</source>
            <translation>%1 tiene un punto en (%2, %3) mm, más allá del límite de %4 mm</translation>
        </message>
        <message>
            <source>%1 has a non-finite coordinate</source>
            <translation>%1 tiene una coordenada no finita</translation>
        </message>
        <message>
            <source>%1 (%2)</source>
            <translation>%1 (%2)</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1: %2</translation>
        </message>
        <message>
            <source>%1: nesting deeper than %2 elements</source>
            <translation>%1: anidamiento de más de %2 elementos</translation>
        </message>
        <message>
            <source>%1: the root element is not &lt;svg&gt;</source>
            <translation>%1: el elemento raíz no es &lt;svg&gt;</translation>
        </message>
        <message>
            <source>cannot open: %1</source>
            <translation>no se puede abrir: %1</translation>
        </message>
        <message>
            <source>cannot read: %1</source>
            <translation>no se puede leer: %1</translation>
        </message>
        <message>
            <source>compressed SVG (gzip): %1</source>
            <translation>SVG comprimido (gzip): %1</translation>
        </message>
        <message>
            <source>could not create a pipe for the SVG worker: %1</source>
            <translation>no se pudo crear una tubería para el proceso SVG: %1</translation>
        </message>
        <message>
            <source>could not start the SVG worker %1: %2</source>
            <translation>no se pudo iniciar el proceso SVG %1: %2</translation>
        </message>
        <message>
            <source>import cancelled</source>
            <translation>importación cancelada</translation>
        </message>
        <message>
            <source>layer "%1" has a non-finite coordinate</source>
            <translation>la capa «%1» tiene una coordenada no finita</translation>
        </message>
        <message>
            <source>layer "%1" has a point at (%2, %3) mm, beyond the %4 mm limit</source>
            <translation>la capa «%1» tiene un punto en (%2; %3) mm, más allá del límite de %4 mm</translation>
        </message>
        <message>
            <source>line %1, column %2: %3</source>
            <translation>línea %1, columna %2: %3</translation>
        </message>
        <message>
            <source>line %1: %2</source>
            <translation>línea %1: %2</translation>
        </message>
        <message>
            <source>line %1: &lt;%2&gt; attribute %3 contains a value that is not a number (%4)</source>
            <translation>línea %1: &lt;%2&gt; atributo %3 contiene un valor que no es un número (%4)</translation>
        </message>
        <message>
            <source>line %1: &lt;%2&gt; attribute %3 contains a number beyond 1e300 (%4)</source>
            <translation>línea %1: &lt;%2&gt; atributo %3 contiene un número mayor que 1e300 (%4)</translation>
        </message>
        <message>
            <source>line %1: &lt;%2&gt;</source>
            <translation>línea %1: &lt;%2&gt;</translation>
        </message>
        <message>
            <source>more than %1 points after flattening (the points budget): reading stopped there</source>
            <translation>más de %1 puntos tras el aplanado (el presupuesto de puntos): la lectura se detuvo ahí</translation>
        </message>
        <message>
            <source>no &lt;svg&gt; element found</source>
            <translation>no se encontró ningún elemento &lt;svg&gt;</translation>
        </message>
        <message>
            <source>no such file</source>
            <translation>el archivo no existe</translation>
        </message>
        <message>
            <source>not readable</source>
            <translation>no se puede leer</translation>
        </message>
        <message>
            <source>root &lt;svg&gt; %1="%2" is not a length</source>
            <translation>&lt;svg&gt; raíz: %1="%2" no es una longitud</translation>
        </message>
        <message>
            <source>root &lt;svg&gt; %1="%2" is zero or negative: nothing to draw</source>
            <translation>&lt;svg&gt; raíz: %1="%2" es cero o negativo: nada que dibujar</translation>
        </message>
        <message>
            <source>root &lt;svg&gt; viewBox="%1": %2</source>
            <translation>&lt;svg&gt; raíz: viewBox="%1": %2</translation>
        </message>
        <message>
            <source>the SVG parser crashed on this file (it is hostile or corrupt, or needed more than the %1 MB memory limit)</source>
            <translation>el analizador SVG falló con este archivo (es malicioso o está dañado, o necesitó más del límite de memoria de %1 MB)</translation>
        </message>
        <message>
            <source>the SVG parser did not finish within %1 s and was stopped (the file is too complex or makes Qt SVG hang)</source>
            <translation>el analizador SVG no terminó en %1 s y se detuvo (el archivo es demasiado complejo o bloquea Qt SVG)</translation>
        </message>
        <message>
            <source>the SVG worker (fivebar-svg-worker) was not found; set ImportOptions::workerPath or FIVEBAR_SVG_WORKER, or install it next to the program</source>
            <translation>no se encontró el proceso SVG (fivebar-svg-worker); defina ImportOptions::workerPath o FIVEBAR_SVG_WORKER, o instálelo junto al programa</translation>
        </message>
        <message>
            <source>the SVG worker ended without a readable result (exit code %1): %2</source>
            <translation>el proceso SVG terminó sin un resultado legible (código de salida %1): %2</translation>
        </message>
        <message>
            <source>the compressed file is empty</source>
            <translation>el archivo comprimido está vacío</translation>
        </message>
        <message>
            <source>the file is empty</source>
            <translation>el archivo está vacío</translation>
        </message>
    </context>
    <context>
        <name>ImportWarning</name>
        <message>
            <source>text in a single-stroke font: per-glyph x/y/dx/dy lists are not followed, only their first value</source>
            <translation>texto en una fuente de trazo simple: las listas x/y/dx/dy por glifo no se siguen, solo su primer valor</translation>
        </message>
        <message>
            <source>text in a single-stroke font: text on a path (&lt;textPath&gt;) is not drawn</source>
            <translation>texto en una fuente de trazo simple: el texto sobre un trazado (&lt;textPath&gt;) no se dibuja</translation>
        </message>
        <message>
            <source>text in a single-stroke font: only UTF-8 documents, this one is %1: its text is drawn as outlines</source>
            <translation>texto en una fuente de trazo simple: solo documentos UTF-8, este es %1: su texto se dibuja como contornos</translation>
        </message>
        <message>
            <source>clip-path set in a style sheet is not applied: those shapes are drawn unclipped</source>
            <translation>clip-path definido en una hoja de estilo no se aplica: esas formas se dibujan sin recortar</translation>
        </message>
        <message>
            <source>%1: its lines there are not drawn</source>
            <translation>%1: sus líneas allí no se dibujan</translation>
        </message>
        <message>
            <source>lines outside the page (the SVG viewport) are not drawn: cut at its edge</source>
            <translation>las líneas fuera de la página (el viewport SVG) no se dibujan: cortadas en su borde</translation>
        </message>
        <message>
            <source>%1: the element is not drawn</source>
            <translation>%1: el elemento no se dibuja</translation>
        </message>
        <message>
            <source>attribute d: path data begins with "%1", not a moveto (M or m): in error from its first command, nothing drawn</source>
            <translation>atributo d: los datos del trazado empiezan por «%1», no por un moveto (M o m): erróneos desde el primer comando, no se dibuja nada</translation>
        </message>
        <message>
            <source>clip-path #%1 not found: drawn unclipped</source>
            <translation>clip-path #%1 no encontrado: se dibuja sin recortar</translation>
        </message>
        <message>
            <source>attribute d: invalid path data at character %1 %2: drawn up to the error</source>
            <translation>atributo d: datos de trazado no válidos en el carácter %1 %2: dibujado hasta el error</translation>
        </message>
        <message>
            <source>attribute d: invalid path data at character %1: drawn up to the error</source>
            <translation>atributo d: datos de trazado no válidos en el carácter %1: dibujado hasta el error</translation>
        </message>
        <message>
            <source>transform-origin="%1" not understood: ignored</source>
            <translation>transform-origin="%1" no reconocido: ignorado</translation>
        </message>
        <message>
            <source>marker #%1 not found: not drawn</source>
            <translation>marcador #%1 no encontrado: no se dibuja</translation>
        </message>
        <message>
            <source>markers on %1 are not drawn (drawn on path, line, polyline and polygon)</source>
            <translation>los marcadores en %1 no se dibujan (se dibujan en path, line, polyline y polygon)</translation>
        </message>
        <message>
            <source>markers set in a style sheet for the selector '%1' are not drawn (only type, #id and .class selectors are applied)</source>
            <translation>los marcadores definidos en una hoja de estilo para el selector '%1' no se dibujan (solo se aplican selectores de tipo, #id y .class)</translation>
        </message>
        <message>
            <source>external reference removed from %1</source>
            <translation>referencia externa eliminada de %1</translation>
        </message>
        <message>
            <source>%1 element removed</source>
            <translation>elemento %1 eliminado</translation>
        </message>
        <message>
            <source>long &lt;path&gt; split into %1 parts to avoid Qt SVG's 32,767-element truncation</source>
            <translation>&lt;path&gt; largo dividido en %1 partes para evitar el truncamiento de Qt SVG a 32.767 elementos</translation>
        </message>
        <message>
            <source>further element warnings not listed</source>
            <translation>no se listan más avisos de elementos</translation>
        </message>
        <message>
            <source>DOCTYPE with entity declarations removed (internal entities were expanded)</source>
            <translation>DOCTYPE con declaraciones de entidades eliminado (las entidades internas se expandieron)</translation>
        </message>
        <message>
            <source>unresolved entity reference dropped</source>
            <translation>referencia a entidad sin resolver descartada</translation>
        </message>
        <message>
            <source>external style sheet (xml-stylesheet) ignored</source>
            <translation>hoja de estilo externa (xml-stylesheet) ignorada</translation>
        </message>
        <message>
            <source>event attribute (on...) removed</source>
            <translation>atributo de evento (on...) eliminado</translation>
        </message>
        <message>
            <source>CSS @import removed</source>
            <translation>@import de CSS eliminado</translation>
        </message>
        <message>
            <source>transform-origin in a style is not applied</source>
            <translation>transform-origin en un estilo no se aplica</translation>
        </message>
        <message>
            <source>mask not applied: masked shapes are drawn whole</source>
            <translation>máscara no aplicada: las formas enmascaradas se dibujan completas</translation>
        </message>
        <message>
            <source>per-glyph rotate on &lt;text&gt; is not applied: glyphs are drawn upright</source>
            <translation>la rotación por glifo en &lt;text&gt; no se aplica: los glifos se dibujan rectos</translation>
        </message>
        <message>
            <source>text on a path (&lt;textPath&gt;) is not drawn</source>
            <translation>el texto sobre trazado (&lt;textPath&gt;) no se dibuja</translation>
        </message>
        <message>
            <source>pattern fills are drawn as outlines, without the pattern</source>
            <translation>los rellenos de patrón se dibujan como contornos, sin el patrón</translation>
        </message>
        <message>
            <source>more than 100000 marker instances: the rest are not drawn</source>
            <translation>más de 100000 instancias de marcador: el resto no se dibuja</translation>
        </message>
        <message>
            <source>marker overflow clipping not applied: marker content is drawn whole</source>
            <translation>recorte de desbordamiento del marcador no aplicado: el contenido del marcador se dibuja completo</translation>
        </message>
        <message>
            <source>no usable width/height/viewBox: page size taken from the drawing's extent</source>
            <translation>sin width/height/viewBox utilizables: tamaño de página tomado de la extensión del dibujo</translation>
        </message>
        <message>
            <source>line %1: %2 %3</source>
            <translation>línea %1: %2 %3</translation>
        </message>
        <message>
            <source>%1 (%2x, first at line %3)</source>
            <translation>%1 (%2x, la primera en la línea %3)</translation>
        </message>
    </context>
    <context>
        <name>ImportWarningsPanel</name>
        <message>
            <source>%1 has %2 points after flattening, more than the budget of %3 (a runaway file?).</source>
            <translation>%1 tiene %2 puntos tras aplanarlo, más que el presupuesto de %3 (¿un archivo desbocado?).</translation>
        </message>
        <message>
            <source>Very large drawing</source>
            <translation>Dibujo muy grande</translation>
        </message>
        <message>
            <source>Planning and plotting it may take very long. Import it anyway?</source>
            <translation>Planificarlo y trazarlo puede tardar mucho. ¿Importarlo de todos modos?</translation>
        </message>
    </context>
    <context>
        <name>JobPipeline</name>
        <message>
            <source>Nothing to plan: the drawing has no visible path.</source>
            <translation>Nada que planificar: el dibujo no tiene ningún trazo visible.</translation>
        </message>
        <message>
            <source>Planning cancelled.</source>
            <translation>Planificación cancelada.</translation>
        </message>
        <message>
            <source>Planned in working mode %1.</source>
            <translation>Planificado en el modo de trabajo %1.</translation>
        </message>
        <message>
            <source>This job is long: about %1 hours and %2 pen-down moves. The machine will be busy all that time. Start it anyway?</source>
            <translation>Este trabajo es largo: unas %1 horas y %2 movimientos con la pluma bajada. La máquina estará ocupada todo ese tiempo. ¿Iniciarlo de todos modos?</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1: %2</translation>
        </message>
        <message>
            <source>%1: cannot write a temporary copy to import</source>
            <translation>%1: no se puede escribir una copia temporal para importar</translation>
        </message>
        <message>
            <source>%1: cannot be imported</source>
            <translation>%1: no se puede importar</translation>
        </message>
        <message>
            <source>%1: cannot read (%2)</source>
            <translation>%1: no se puede leer (%2)</translation>
        </message>
        <message>
            <source>no machine profile given</source>
            <translation>no se indicó ningún perfil de máquina</translation>
        </message>
    </context>
    <context>
        <name>MapPainter</name>
        <message>
            <source>Transmission angle at the pen (deg)</source>
            <translation>Ángulo de transmisión en la pluma (°)</translation>
        </message>
        <message>
            <source>Conditioning (1 = isotropic)</source>
            <translation>Condicionamiento (1 = isótropo)</translation>
        </message>
        <message>
            <source>Resolution (um per motor step)</source>
            <translation>Resolución (µm por paso de motor)</translation>
        </message>
    </context>
    <context>
        <name>Placement</name>
        <message>
            <source>scaled to %1 % to fit the workspace</source>
            <translation>reducido al %1 % para caber en el espacio de trabajo</translation>
        </message>
    </context>
    <context>
        <name>Planner</name>
        <message>
            <source>layer '%1'</source>
            <translation>capa '%1'</translation>
        </message>
        <message>
            <source>layer %1</source>
            <translation>capa %1</translation>
        </message>
        <message>
            <source>move or shrink the drawing (--at, --scale, --fit)</source>
            <translation>mover o reducir el dibujo (--at, --scale, --fit)</translation>
        </message>
        <message>
            <source>try another working mode (--mode)</source>
            <translation>probar otro modo de trabajo (--mode)</translation>
        </message>
        <message>
            <source>travel back to the start pose</source>
            <translation>desplazamiento de vuelta a la posición inicial</translation>
        </message>
        <message>
            <source>start pose</source>
            <translation>posición inicial</translation>
        </message>
        <message>
            <source>the profile's home pose does not close the linkage</source>
            <translation>la posición de inicio del perfil no cierra el mecanismo</translation>
        </message>
        <message>
            <source>set a reachable home pose in the profile</source>
            <translation>fijar una posición de inicio alcanzable en el perfil</translation>
        </message>
        <message>
            <source>a point is out of reach in working mode %1</source>
            <translation>un punto está fuera de alcance en el modo de trabajo %1</translation>
        </message>
        <message>
            <source>the drawn curve cannot follow the stroke here (singular region)</source>
            <translation>la curva trazada no puede seguir el trazo aquí (zona singular)</translation>
        </message>
        <message>
            <source>the drawn line %1</source>
            <translation>la línea trazada %1</translation>
        </message>
        <message>
            <source>travel to %1</source>
            <translation>desplazamiento a %1</translation>
        </message>
        <message>
            <source>no safe pen-up travel reaches it</source>
            <translation>ningún desplazamiento seguro con la pluma levantada lo alcanza</translation>
        </message>
        <message>
            <source>move the drawing away from singular regions (--at)</source>
            <translation>alejar el dibujo de las zonas singulares (--at)</translation>
        </message>
        <message>
            <source>try another --mode</source>
            <translation>probar otro --mode</translation>
        </message>
        <message>
            <source>%1 path %2</source>
            <translation>%1 trazado %2</translation>
        </message>
        <message>
            <source>tolerance %1 mm leaves nothing for the moves after flattening (%2 mm) and the G-code rounding (up to %3 mm)</source>
            <translation>la tolerancia de %1 mm no deja nada para los movimientos tras el aplanado (%2 mm) y el redondeo del G-code (hasta %3 mm)</translation>
        </message>
        <message>
            <source>backlash compensation</source>
            <translation>compensación de holgura</translation>
        </message>
        <message>
            <source>move the drawing away from the workspace edge (--at)</source>
            <translation>alejar el dibujo del borde del espacio de trabajo (--at)</translation>
        </message>
        <message>
            <source>planning cancelled</source>
            <translation>planificación cancelada</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1: %2</translation>
        </message>
        <message>
            <source>backlash compensation: a compensated move %1</source>
            <translation>compensación de holgura: un movimiento compensado %1</translation>
        </message>
        <message>
            <source>shrink the drawing to %1 % (--scale %2)</source>
            <translation>reducir el dibujo al %1 % (--scale %2)</translation>
        </message>
        <message>
            <source>move the drawing's centre to x %1 mm, y %2 mm (--at %3,%4)</source>
            <translation>mover el centro del dibujo a x %1 mm, y %2 mm (--at %3,%4)</translation>
        </message>
        <message>
            <source>use working mode %1 (--mode %1)</source>
            <translation>usar el modo de trabajo %1 (--mode %1)</translation>
        </message>
        <message>
            <source>fit the drawing into the workspace (--fit)</source>
            <translation>ajustar el dibujo al espacio de trabajo (--fit)</translation>
        </message>
        <message>
            <source>job</source>
            <translation>trabajo</translation>
        </message>
        <message>
            <source>working mode %1: %2: %3</source>
            <translation>modo de trabajo %1: %2: %3</translation>
        </message>
        <message>
            <source>scale must be a positive number</source>
            <translation>la escala debe ser un número positivo</translation>
        </message>
        <message>
            <source>nothing visible to draw in '%1'</source>
            <translation>nada visible que dibujar en '%1'</translation>
        </message>
        <message>
            <source>no working mode has a singularity-free area to place the drawing in</source>
            <translation>ningún modo de trabajo tiene una zona sin singularidades donde colocar el dibujo</translation>
        </message>
        <message>
            <source>check the profile</source>
            <translation>revisar el perfil</translation>
        </message>
        <message>
            <source>the drawing was flattened within %1 mm, too coarse at %2 %: import it again within %3 mm</source>
            <translation>el dibujo se aplanó con %1 mm de precisión, demasiado basto al %2 %: impórtelo de nuevo con %3 mm</translation>
        </message>
        <message>
            <source>move or shrink the drawing in the Placement panel</source>
            <translation>mover o reducir el dibujo en el panel Colocación</translation>
        </message>
        <message>
            <source>try another working mode in the Workspace panel</source>
            <translation>probar otro modo de trabajo en el panel Espacio de trabajo</translation>
        </message>
        <message>
            <source>move the drawing away from singular regions in the Placement panel</source>
            <translation>alejar el dibujo de las zonas singulares en el panel Colocación</translation>
        </message>
        <message>
            <source>move the drawing away from the workspace edge in the Placement panel</source>
            <translation>alejar el dibujo del borde del espacio de trabajo en el panel Colocación</translation>
        </message>
        <message>
            <source>set Scale to %1 % in the Placement panel</source>
            <translation>poner «Escala» en %1 % en el panel Colocación</translation>
        </message>
        <message>
            <source>set Centre X to %1 mm and Centre Y to %2 mm in the Placement panel</source>
            <translation>poner «Centro X» en %1 mm y «Centro Y» en %2 mm en el panel Colocación</translation>
        </message>
        <message>
            <source>choose working mode %1 in the Workspace panel</source>
            <translation>elegir el modo de trabajo %1 en el panel Espacio de trabajo</translation>
        </message>
        <message>
            <source>press Fit to workspace in the Placement panel</source>
            <translation>pulsar «Ajustar al espacio» en el panel Colocación</translation>
        </message>
    </context>
    <context>
        <name>Preflight</name>
        <message>
            <source>layer %1 path %2 point %3 at (%4, %5) mm</source>
            <translation>capa %1 trazado %2 punto %3 en (%4; %5) mm</translation>
        </message>
        <message>
            <source>%1 is out of reach of leg %2</source>
            <translation>%1 está fuera del alcance del brazo %2</translation>
        </message>
        <message>
            <source>%1 needs assembly mode %2 in working mode %3</source>
            <translation>%1 necesita el modo de ensamblaje %2 en el modo de trabajo %3</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1: %2</translation>
        </message>
        <message>
            <source>the line to %1 %2</source>
            <translation>la línea a %1 %2</translation>
        </message>
        <message>
            <source>the travel back to the home pose</source>
            <translation>el desplazamiento de vuelta a la posición de inicio</translation>
        </message>
        <message>
            <source>the travel to %1</source>
            <translation>el desplazamiento a %1</translation>
        </message>
        <message>
            <source>%1 %2</source>
            <translation>%1 %2</translation>
        </message>
        <message>
            <source>%1; no safe detour found</source>
            <translation>%1; no se encontró ningún rodeo seguro</translation>
        </message>
        <message>
            <source>%1; detour not searched (limit of searches per job reached)</source>
            <translation>%1; rodeo no buscado (límite de búsquedas por trabajo alcanzado)</translation>
        </message>
        <message>
            <source>mode %1: feasible, worst type II margin %2 deg</source>
            <translation>modo %1: factible, peor margen tipo II %2°</translation>
        </message>
        <message>
            <source>mode %1: 1 problem</source>
            <translation>modo %1: 1 problema</translation>
        </message>
        <message>
            <source>mode %1: %2 problems</source>
            <translation>modo %1: %2 problemas</translation>
        </message>
        <message>
            <source>%1 (first: %2)</source>
            <translation>%1 (primero: %2)</translation>
        </message>
        <message>
            <source>%1; fix: shrink to %2%</source>
            <translation>%1; solución: reducir al %2 %</translation>
        </message>
        <message>
            <source>%1; fix: move the centre to (%2, %3) mm</source>
            <translation>%1; solución: mover el centro a (%2; %3) mm</translation>
        </message>
        <message>
            <source>point %1 at (%2, %3) mm</source>
            <translation>punto %1 en (%2; %3) mm</translation>
        </message>
    </context>
    <context>
        <name>QObject</name>
        <message>
            <source>Planning failed: %1</source>
            <translation>La planificación falló: %1</translation>
        </message>
        <message>
            <source>Cannot write %1: %2</source>
            <translation>No se puede escribir %1: %2</translation>
        </message>
    </context>
    <context>
        <name>Safety</name>
        <message>
            <source>safe; closest approach to a type II singularity %1 deg</source>
            <translation>seguro; máxima aproximación a una singularidad de tipo II %1°</translation>
        </message>
        <message>
            <source>passes within %1 deg of a type II singularity at (%2, %3) mm, %4% along the move</source>
            <translation>pasa a menos de %1° de una singularidad de tipo II en (%2; %3) mm, al %4 % del movimiento</translation>
        </message>
        <message>
            <source>a leg comes too close to full stretch or fold (type I) at (%1, %2) mm, %3% along the move</source>
            <translation>un brazo se acerca demasiado a la extensión o el pliegue completo (tipo I) en (%1; %2) mm, al %3 % del movimiento</translation>
        </message>
        <message>
            <source>goes beyond a motor's joint limit at (%1, %2) mm, %3% along the move</source>
            <translation>sobrepasa el límite articular de un motor en (%1; %2) mm, al %3 % del movimiento</translation>
        </message>
        <message>
            <source>leaves the reachable workspace (the linkage cannot close) at (%1, %2) mm, %3% along the move</source>
            <translation>sale del espacio de trabajo alcanzable (el mecanismo no puede cerrarse) en (%1; %2) mm, al %3 % del movimiento</translation>
        </message>
        <message>
            <source>passes through a type II singularity, where the assembly mode can flip at (%1, %2) mm, %3% along the move</source>
            <translation>atraviesa una singularidad de tipo II, donde el modo de ensamblaje puede cambiar, en (%1; %2) mm, al %3 % del movimiento</translation>
        </message>
        <message>
            <source>unknown move status</source>
            <translation>estado de movimiento desconocido</translation>
        </message>
    </context>
    <context>
        <name>WorkspaceLegend</name>
        <message>
            <source>type II &gt;= %1 deg, type I &gt;= %2 deg</source>
            <translation>tipo II &gt;= %1°, tipo I &gt;= %2°</translation>
        </message>
        <message>
            <source>none</source>
            <translation>ninguno</translation>
        </message>
        <message>
            <source>singularity-free (%1)</source>
            <translation>sin singularidades (%1)</translation>
        </message>
        <message>
            <source>reachable, within a singularity margin</source>
            <translation>alcanzable, dentro de un margen de singularidad</translation>
        </message>
        <message>
            <source>reach boundary</source>
            <translation>límite de alcance</translation>
        </message>
        <message>
            <source>singularity-free boundary</source>
            <translation>límite de la zona sin singularidades</translation>
        </message>
        <message>
            <source>type II singularity (%1 curves)</source>
            <translation>singularidad de tipo II (%1 curvas)</translation>
        </message>
        <message>
            <source>largest rectangle: %1</source>
            <translation>mayor rectángulo: %1</translation>
        </message>
        <message>
            <source>reachable area: %1 cm²</source>
            <translation>área alcanzable: %1 cm²</translation>
        </message>
        <message>
            <source>singularity-free area: %1 cm²</source>
            <translation>área sin singularidades: %1 cm²</translation>
        </message>
    </context>
    <context>
        <name>fivebar::studio::FileActions</name>
        <message>
            <source>Unsaved changes</source>
            <translation>Cambios sin guardar</translation>
        </message>
        <message>
            <source>%1 has changes that are not saved. Save them first?</source>
            <translation>%1 tiene cambios sin guardar. ¿Guardarlos primero?</translation>
        </message>
        <message>
            <source>Cannot save %1: %2</source>
            <translation>No se puede guardar %1: %2</translation>
        </message>
        <message>
            <source>Nothing to save: open a drawing first.</source>
            <translation>Nada que guardar: abre primero un dibujo.</translation>
        </message>
        <message>
            <source>Save failed</source>
            <translation>Error al guardar</translation>
        </message>
        <message>
            <source>Saved %1</source>
            <translation>%1 guardado</translation>
        </message>
        <message>
            <source>Save project</source>
            <translation>Guardar proyecto</translation>
        </message>
        <message>
            <source>FiveBar projects (*.fivebar)</source>
            <translation>Proyectos FiveBar (*.fivebar)</translation>
        </message>
        <message>
            <source>The job is still being planned; export it when planning is done.</source>
            <translation>El trabajo aún se está planificando; expórtalo cuando termine la planificación.</translation>
        </message>
        <message>
            <source>There is no planned job to export (see the job preview).</source>
            <translation>No hay ningún trabajo planificado que exportar (ver la vista previa del trabajo).</translation>
        </message>
        <message>
            <source>Cannot write %1: %2</source>
            <translation>No se puede escribir %1: %2</translation>
        </message>
        <message>
            <source>Export G-code</source>
            <translation>Exportar código G</translation>
        </message>
        <message>
            <source>G-code (*.gcode *.nc);;All files (*)</source>
            <translation>Código G (*.gcode *.nc);;Todos los archivos (*)</translation>
        </message>
        <message>
            <source>Exported %1</source>
            <translation>%1 exportado</translation>
        </message>
        <message>
            <source>Clear list</source>
            <translation>Vaciar lista</translation>
        </message>
        <message>
            <source>The untitled project made from %1 has changes that are not saved. Save it as a project first?</source>
            <translation>El proyecto sin título creado a partir de %1 tiene cambios sin guardar. ¿Guardarlo primero como proyecto?</translation>
        </message>
    </context>
    <context>
        <name>fivebar::studio::LanguageMenu</name>
        <message>
            <source>&amp;Language</source>
            <translation>&amp;Idioma</translation>
        </message>
        <message>
            <source>System default</source>
            <translation>Idioma del sistema</translation>
        </message>
        <message>
            <source>Language</source>
            <translation>Idioma</translation>
        </message>
        <message>
            <source>The new language applies when FiveBar Studio starts again.</source>
            <translation>El nuevo idioma se aplica la próxima vez que se inicie FiveBar Studio.</translation>
        </message>
    </context>
    <context>
        <name>fivebar::studio::MainWindow</name>
        <message>
            <source>FiveBar Studio</source>
            <translation>FiveBar Studio</translation>
        </message>
        <message>
            <source>x %1 mm, y %2 mm</source>
            <translation>x %1 mm, y %2 mm</translation>
        </message>
        <message>
            <source>Planning...</source>
            <translation>Planificando…</translation>
        </message>
        <message>
            <source>Workspace</source>
            <translation>Espacio de trabajo</translation>
        </message>
        <message>
            <source>Placement</source>
            <translation>Colocación</translation>
        </message>
        <message>
            <source>Layers</source>
            <translation>Capas</translation>
        </message>
        <message>
            <source>Job preview</source>
            <translation>Vista previa del trabajo</translation>
        </message>
        <message>
            <source>Simulation</source>
            <translation>Simulación</translation>
        </message>
        <message>
            <source>&amp;File</source>
            <translation>&amp;Archivo</translation>
        </message>
        <message>
            <source>Open &amp;recent</source>
            <translation>Abrir &amp;reciente</translation>
        </message>
        <message>
            <source>&amp;Quit</source>
            <translation>&amp;Salir</translation>
        </message>
        <message>
            <source>&amp;Edit</source>
            <translation>&amp;Editar</translation>
        </message>
        <message>
            <source>&amp;Undo</source>
            <translation>&amp;Deshacer</translation>
        </message>
        <message>
            <source>&amp;Redo</source>
            <translation>&amp;Rehacer</translation>
        </message>
        <message>
            <source>&amp;Fit drawing to workspace</source>
            <translation>&amp;Ajustar el dibujo al espacio de trabajo</translation>
        </message>
        <message>
            <source>Ctrl+F</source>
            <translation>Ctrl+F</translation>
        </message>
        <message>
            <source>&amp;View</source>
            <translation>&amp;Ver</translation>
        </message>
        <message>
            <source>Zoom &amp;in</source>
            <translation>&amp;Acercar</translation>
        </message>
        <message>
            <source>Ctrl+=</source>
            <translation>Ctrl+=</translation>
        </message>
        <message>
            <source>Zoom &amp;out</source>
            <translation>A&amp;lejar</translation>
        </message>
        <message>
            <source>Zoom to &amp;fit</source>
            <translation>&amp;Ajustar a la vista</translation>
        </message>
        <message>
            <source>Ctrl+0</source>
            <translation>Ctrl+0</translation>
        </message>
        <message>
            <source>&amp;Simulation</source>
            <translation>Si&amp;mulación</translation>
        </message>
        <message>
            <source>&amp;Play / pause</source>
            <translation>&amp;Reproducir / pausa</translation>
        </message>
        <message>
            <source>F5</source>
            <translation>F5</translation>
        </message>
        <message>
            <source>Step &amp;forward</source>
            <translation>Paso a&amp;delante</translation>
        </message>
        <message>
            <source>F6</source>
            <translation>F6</translation>
        </message>
        <message>
            <source>Step &amp;back</source>
            <translation>Paso a&amp;trás</translation>
        </message>
        <message>
            <source>Shift+F6</source>
            <translation>Shift+F6</translation>
        </message>
        <message>
            <source>&amp;Machine</source>
            <translation>&amp;Máquina</translation>
        </message>
        <message>
            <source>&amp;Help</source>
            <translation>A&amp;yuda</translation>
        </message>
        <message>
            <source>&amp;About FiveBar Studio</source>
            <translation>&amp;Acerca de FiveBar Studio</translation>
        </message>
        <message>
            <source>About FiveBar Studio</source>
            <translation>Acerca de FiveBar Studio</translation>
        </message>
        <message>
            <source>&lt;b&gt;FiveBar Studio %1&lt;/b&gt;&lt;p&gt;Plans and simulates drawings for five-bar linkage robots: workspace and singularity analysis, safe job planning, GRBL output.&lt;/p&gt;</source>
            <translation>&lt;b&gt;FiveBar Studio %1&lt;/b&gt;&lt;p&gt;Planifica y simula dibujos para robots de cinco barras: análisis del espacio de trabajo y de las singularidades, planificación segura de trabajos, salida GRBL.&lt;/p&gt;</translation>
        </message>
        <message>
            <source>Main</source>
            <translation>Principal</translation>
        </message>
        <message>
            <source>&amp;Open drawing or project...</source>
            <translation>&amp;Abrir dibujo o proyecto…</translation>
        </message>
        <message>
            <source>&amp;Save project</source>
            <translation>&amp;Guardar proyecto</translation>
        </message>
        <message>
            <source>Save project &amp;as...</source>
            <translation>Guardar proyecto &amp;como…</translation>
        </message>
        <message>
            <source>&amp;Export G-code...</source>
            <translation>&amp;Exportar código G…</translation>
        </message>
        <message>
            <source>Ctrl+E</source>
            <translation>Ctrl+E</translation>
        </message>
        <message>
            <source>&amp;Actual size (100 %)</source>
            <translation>&amp;Tamaño real (100 %)</translation>
        </message>
        <message>
            <source>Ctrl+1</source>
            <translation>Ctrl+1</translation>
        </message>
        <message>
            <source>%1[*] - FiveBar Studio</source>
            <translation>%1[*] - FiveBar Studio</translation>
        </message>
        <message>
            <source>Fills</source>
            <translation>Rellenos</translation>
        </message>
        <message>
            <source>Import warnings</source>
            <translation>Avisos de importación</translation>
        </message>
        <message>
            <source>Untitled project (%1)[*] - FiveBar Studio</source>
            <translation>Proyecto sin título (%1)[*] - FiveBar Studio</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::ConsolePanel</name>
        <message>
            <source>Lines sent to and received from the machine appear here.</source>
            <translation>Aquí aparecen las líneas enviadas a la máquina y recibidas de ella.</translation>
        </message>
        <message>
            <source>Send</source>
            <translation>Enviar</translation>
        </message>
        <message>
            <source>G-code or $ command, e.g. $$ or $I; moves are checked first</source>
            <translation>G-code u orden $, p. ej. $$ o $I; los movimientos se comprueban antes</translation>
        </message>
        <message>
            <source>Send unchecked (expert)</source>
            <translation>Enviar sin comprobar (experto)</translation>
        </message>
        <message>
            <source>Send lines without the motion check. X and Y are motor angles in degrees: a wrong number swings an arm across the base.</source>
            <translation>Enviar líneas sin la comprobación de movimiento. X e Y son ángulos de motor en grados: un número erróneo hace girar un brazo contra la base.</translation>
        </message>
        <message>
            <source>Unchecked console: lines go to the machine as typed, without the motion check. A wrong X or Y (motor angles in degrees) can drive the arms into each other or the base.</source>
            <translation>Consola sin comprobar: las líneas van a la máquina tal como se escriben, sin la comprobación de movimiento. Una X o Y errónea (ángulos de motor en grados) puede hacer chocar los brazos entre sí o con la base.</translation>
        </message>
        <message>
            <source>Not sent: %1</source>
            <translation>No enviado: %1</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::DesignDialog</name>
        <message>
            <source>Design a machine</source>
            <translation>Diseñar una máquina</translation>
        </message>
        <message>
            <source>&amp;Design...</source>
            <translation>&amp;Diseño…</translation>
        </message>
        <message>
            <source>Choose link lengths for a paper size</source>
            <translation>Elegir las longitudes de los brazos para un tamaño de papel</translation>
        </message>
        <message>
            <source>Brief</source>
            <translation>Requisitos</translation>
        </message>
        <message>
            <source>Custom</source>
            <translation>Personalizado</translation>
        </message>
        <message>
            <source>Landscape</source>
            <translation>Horizontal</translation>
        </message>
        <message>
            <source>Portrait</source>
            <translation>Vertical</translation>
        </message>
        <message>
            <source> mm</source>
            <translation> mm</translation>
        </message>
        <message>
            <source> deg</source>
            <translation> °</translation>
        </message>
        <message>
            <source>Symmetric arms</source>
            <translation>Brazos simétricos</translation>
        </message>
        <message>
            <source>Any</source>
            <translation>Cualquiera</translation>
        </message>
        <message>
            <source>Worst condition number</source>
            <translation>Peor número de condición</translation>
        </message>
        <message>
            <source>Worst resolution</source>
            <translation>Peor resolución</translation>
        </message>
        <message>
            <source>Footprint</source>
            <translation>Superficie ocupada</translation>
        </message>
        <message>
            <source>Weighted mix</source>
            <translation>Mezcla ponderada</translation>
        </message>
        <message>
            <source>Condition</source>
            <translation>Condición</translation>
        </message>
        <message>
            <source>Resolution</source>
            <translation>Resolución</translation>
        </message>
        <message>
            <source>Weight of this normalised term in the weighted mix</source>
            <translation>Peso de este término normalizado en la mezcla ponderada</translation>
        </message>
        <message>
            <source>Mix weights</source>
            <translation>Pesos de la mezcla</translation>
        </message>
        <message>
            <source>Paper</source>
            <translation>Papel</translation>
        </message>
        <message>
            <source>Orientation</source>
            <translation>Orientación</translation>
        </message>
        <message>
            <source>Width</source>
            <translation>Ancho</translation>
        </message>
        <message>
            <source>Height</source>
            <translation>Alto</translation>
        </message>
        <message>
            <source>Margin</source>
            <translation>Margen</translation>
        </message>
        <message>
            <source>Shortest link</source>
            <translation>Brazo más corto</translation>
        </message>
        <message>
            <source>Longest link</source>
            <translation>Brazo más largo</translation>
        </message>
        <message>
            <source>Smallest motor spacing</source>
            <translation>Menor distancia entre motores</translation>
        </message>
        <message>
            <source>Largest motor spacing</source>
            <translation>Mayor distancia entre motores</translation>
        </message>
        <message>
            <source>Arm clearance</source>
            <translation>Holgura de los brazos</translation>
        </message>
        <message>
            <source>Type II margin</source>
            <translation>Margen tipo II</translation>
        </message>
        <message>
            <source>Working mode</source>
            <translation>Modo de trabajo</translation>
        </message>
        <message>
            <source>Objective</source>
            <translation>Objetivo</translation>
        </message>
        <message>
            <source>Search</source>
            <translation>Buscar</translation>
        </message>
        <message>
            <source>Cancel</source>
            <translation>Cancelar</translation>
        </message>
        <message>
            <source>Set the brief and press Search.</source>
            <translation>Fija los requisitos y pulsa Buscar.</translation>
        </message>
        <message>
            <source>Worst condition</source>
            <translation>Peor condición</translation>
        </message>
        <message>
            <source>Footprint (cm²)</source>
            <translation>Superficie ocupada (cm²)</translation>
        </message>
        <message>
            <source>µm/step</source>
            <translation>µm/paso</translation>
        </message>
        <message>
            <source>Mode</source>
            <translation>Modo</translation>
        </message>
        <message>
            <source>Workspace</source>
            <translation>Espacio de trabajo</translation>
        </message>
        <message>
            <source>Conditioning</source>
            <translation>Condicionamiento</translation>
        </message>
        <message>
            <source>Transmission angle</source>
            <translation>Ángulo de transmisión</translation>
        </message>
        <message>
            <source>Map on the canvas</source>
            <translation>Mapa en el lienzo</translation>
        </message>
        <message>
            <source>Use as profile</source>
            <translation>Usar como perfil</translation>
        </message>
        <message>
            <source>Export...</source>
            <translation>Exportar…</translation>
        </message>
        <message>
            <source>Searching...</source>
            <translation>Buscando…</translation>
        </message>
        <message>
            <source>Search cancelled.</source>
            <translation>Búsqueda cancelada.</translation>
        </message>
        <message>
            <source>No design meets the brief: %1</source>
            <translation>Ningún diseño cumple los requisitos: %1</translation>
        </message>
        <message>
            <source>Best worst-case condition number %1; %2 designs on the trade-off, %3 evaluations in %4 s.</source>
            <translation>Mejor número de condición en el peor caso %1; %2 diseños en el compromiso, %3 evaluaciones en %4 s.</translation>
        </message>
        <message>
            <source>The document now uses this design (Edit &gt; Undo restores the previous profile).</source>
            <translation>El documento usa ahora este diseño (Editar &gt; Deshacer restaura el perfil anterior).</translation>
        </message>
        <message>
            <source>No design is selected.</source>
            <translation>No hay ningún diseño seleccionado.</translation>
        </message>
        <message>
            <source>Export profile</source>
            <translation>Exportar perfil</translation>
        </message>
        <message>
            <source>Machine profiles (*.json)</source>
            <translation>Perfiles de máquina (*.json)</translation>
        </message>
        <message>
            <source>Profile written to %1.</source>
            <translation>Perfil escrito en %1.</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::FillOptionsBox</name>
        <message>
            <source>Draw dashed strokes solid</source>
            <translation>Dibujar los trazos discontinuos como continuos</translation>
        </message>
        <message>
            <source>Dashed strokes are drawn as their dashes, the pen lifted between them; checked: each dashed stroke is drawn as one line.</source>
            <translation>Los trazos discontinuos se dibujan guion a guion, con el lápiz levantado entre ellos; marcado: cada trazo discontinuo se dibuja como una sola línea.</translation>
        </message>
        <message>
            <source>Filled shapes</source>
            <translation>Formas rellenas</translation>
        </message>
        <message>
            <source>Outline</source>
            <translation>Contorno</translation>
        </message>
        <message>
            <source>Hatch</source>
            <translation>Rayado</translation>
        </message>
        <message>
            <source>Not drawn</source>
            <translation>Sin dibujar</translation>
        </message>
        <message>
            <source>Outline: the shape's edge (as AxiDraw and vpype draw fills). Hatch: parallel lines inside the shape. Not drawn: fill-only shapes are left out.</source>
            <translation>Contorno: el borde de la forma (como dibujan los rellenos AxiDraw y vpype). Rayado: líneas paralelas dentro de la forma. Sin dibujar: se omiten las formas que solo tienen relleno.</translation>
        </message>
        <message>
            <source> mm</source>
            <translation> mm</translation>
        </message>
        <message>
            <source> deg</source>
            <translation> °</translation>
        </message>
        <message>
            <source>Crosshatch</source>
            <translation>Rayado cruzado</translation>
        </message>
        <message>
            <source>Keep the outline</source>
            <translation>Mantener el contorno</translation>
        </message>
        <message>
            <source>Import again with these settings</source>
            <translation>Volver a importar con estos ajustes</translation>
        </message>
        <message>
            <source>Fill:</source>
            <translation>Relleno:</translation>
        </message>
        <message>
            <source>Line spacing:</source>
            <translation>Separación:</translation>
        </message>
        <message>
            <source>Angle:</source>
            <translation>Ángulo:</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::GoToTool</name>
        <message>
            <source>Connect the machine first: its position is not known.</source>
            <translation>Conecta primero la máquina: su posición es desconocida.</translation>
        </message>
        <message>
            <source>Cannot go there: %1</source>
            <translation>No se puede ir allí: %1</translation>
        </message>
        <message numerus="yes">
            <source>Go to %1, %2 mm? The dashed path is the pen's travel (%n checked move(s)).</source>
            <translation>
                <numerusform>¿Ir a %1, %2 mm? El trazo discontinuo es el recorrido de la pluma (%n movimiento comprobado).</numerusform>
                <numerusform>¿Ir a %1, %2 mm? El trazo discontinuo es el recorrido de la pluma (%n movimientos comprobados).</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::ImportController</name>
        <message>
            <source>%1: another import is still running.</source>
            <translation>%1: aún hay otra importación en curso.</translation>
        </message>
        <message>
            <source>Importing %1...</source>
            <translation>Importando %1…</translation>
        </message>
        <message>
            <source>Cancel</source>
            <translation>Cancelar</translation>
        </message>
        <message>
            <source>Import</source>
            <translation>Importación</translation>
        </message>
        <message>
            <source>Import of %1 cancelled.</source>
            <translation>Importación de %1 cancelada.</translation>
        </message>
        <message>
            <source>%1 could not be imported.</source>
            <translation>No se pudo importar %1.</translation>
        </message>
        <message>
            <source>Import failed</source>
            <translation>Error de importación</translation>
        </message>
        <message>
            <source>%1 contains nothing to draw.</source>
            <translation>%1 no contiene nada que dibujar.</translation>
        </message>
        <message>
            <source>Open drawing or project</source>
            <translation>Abrir dibujo o proyecto</translation>
        </message>
        <message>
            <source>Drawings and projects (*.svg *.fivebar);;SVG drawings (*.svg);;FiveBar projects (*.fivebar);;All files (*)</source>
            <translation>Dibujos y proyectos (*.svg *.fivebar);;Dibujos SVG (*.svg);;Proyectos FiveBar (*.fivebar);;Todos los archivos (*)</translation>
        </message>
        <message>
            <source>Very large drawing</source>
            <translation>Dibujo muy grande</translation>
        </message>
        <message>
            <source>%1 has more than %2 points after flattening (a runaway file?). Reading it was stopped there.

Planning and plotting it may take very long. Import it whole anyway?</source>
            <translation>%1 tiene más de %2 puntos tras aplanarlo (¿un archivo desbocado?). La lectura se detuvo ahí.

Planificarlo y plotearlo puede tardar mucho. ¿Importarlo entero de todos modos?</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::ImportWarningsPanel</name>
        <message>
            <source>No drawing imported yet.</source>
            <translation>Aún no se ha importado ningún dibujo.</translation>
        </message>
        <message>
            <source>What the importer dropped, approximated or could not draw. docs/svg-import.md lists what is supported.</source>
            <translation>Lo que la importación omitió, aproximó o no pudo dibujar. docs/svg-import.md enumera lo que se admite.</translation>
        </message>
        <message>
            <source>%1 imported without warnings.</source>
            <translation>%1 importado sin avisos.</translation>
        </message>
        <message>
            <source>1 warning while importing %1: part of the drawing may differ from what a browser shows.</source>
            <translation>1 aviso al importar %1: parte del dibujo puede diferir de lo que muestra un navegador.</translation>
        </message>
        <message>
            <source>%1 warnings while importing %2: parts of the drawing may differ from what a browser shows.</source>
            <translation>%1 avisos al importar %2: partes del dibujo pueden diferir de lo que muestra un navegador.</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::JobLayer</name>
        <message>
            <source>Planning...</source>
            <translation>Planificando…</translation>
        </message>
    </context>
    <context>
        <name>fivebar::session::JogController</name>
        <message>
            <source>Jog refused: the machine is not connected, not idle, or a job is running.</source>
            <translation>Movimiento rechazado: la máquina no está conectada, no está en reposo o hay un trabajo en curso.</translation>
        </message>
        <message>
            <source>Jog stopped at the last safe point: %1</source>
            <translation>Movimiento detenido en el último punto seguro: %1</translation>
        </message>
        <message>
            <source>Jog refused: %1</source>
            <translation>Movimiento rechazado: %1</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::JogPanel</name>
        <message>
            <source>Frame the job</source>
            <translation>Recorrer el contorno del trabajo</translation>
        </message>
        <message>
            <source>Trace the outline of the planned job with the pen up (a laser at low power), along checked moves, to see where the drawing lands on the paper</source>
            <translation>Recorrer el contorno del trabajo planificado con el bolígrafo levantado (un láser a baja potencia), con movimientos comprobados, para ver dónde queda el dibujo en el papel</translation>
        </message>
        <message>
            <source>Tracing the job's outline with the pen up.</source>
            <translation>Recorriendo el contorno del trabajo con el bolígrafo levantado.</translation>
        </message>
        <message>
            <source>Jog the pen %1 mm in X, %2 mm in Y per step; hold for a continuous jog</source>
            <translation>Mover la pluma %1 mm en X y %2 mm en Y por paso; mantén pulsado para un movimiento continuo</translation>
        </message>
        <message>
            <source>Go to…</source>
            <translation>Ir a…</translation>
        </message>
        <message>
            <source>Click the canvas to choose where the pen goes; the path is shown before you confirm.</source>
            <translation>Haz clic en el lienzo para elegir adónde va la pluma; el recorrido se muestra antes de confirmar.</translation>
        </message>
        <message>
            <source>Turn motor %1 clockwise by one step</source>
            <translation>Girar el motor %1 un paso en sentido horario</translation>
        </message>
        <message>
            <source>Turn motor %1 counter-clockwise by one step</source>
            <translation>Girar el motor %1 un paso en sentido antihorario</translation>
        </message>
        <message>
            <source>Step</source>
            <translation>Paso</translation>
        </message>
        <message>
            <source>mm / °</source>
            <translation>mm / °</translation>
        </message>
        <message>
            <source> mm/s</source>
            <translation> mm/s</translation>
        </message>
        <message>
            <source>Pen up</source>
            <translation>Subir pluma</translation>
        </message>
        <message>
            <source>Lift the pen (Page Up on the canvas)</source>
            <translation>Subir la pluma (Re Pág en el lienzo)</translation>
        </message>
        <message>
            <source>Pen down</source>
            <translation>Bajar pluma</translation>
        </message>
        <message>
            <source>Lower the pen (Page Down on the canvas)</source>
            <translation>Bajar la pluma (Av Pág en el lienzo)</translation>
        </message>
        <message>
            <source>Go</source>
            <translation>Ir</translation>
        </message>
        <message>
            <source>Cancel</source>
            <translation>Cancelar</translation>
        </message>
        <message>
            <source>Click the canvas where the pen should go.</source>
            <translation>Haz clic en el lienzo donde debe ir la pluma.</translation>
        </message>
        <message>
            <source>Home ($H)</source>
            <translation>Origen ($H)</translation>
        </message>
        <message>
            <source>Set reference pose</source>
            <translation>Fijar pose de referencia</translation>
        </message>
        <message>
            <source>Run the homing cycle</source>
            <translation>Ejecutar la búsqueda de origen</translation>
        </message>
        <message>
            <source>Declare that the machine now stands at the profile's home pose</source>
            <translation>Declarar que la máquina está ahora en la pose de origen del perfil</translation>
        </message>
        <message>
            <source>Speed of XY jogs</source>
            <translation>Velocidad de los movimientos XY</translation>
        </message>
        <message>
            <source>Go to home pose</source>
            <translation>Ir a la posición de inicio</translation>
        </message>
        <message>
            <source>Move the pen up to the profile's home pose by a checked move (the reference must be set)</source>
            <translation>Ir con la pluma levantada a la posición de inicio del perfil mediante un movimiento comprobado (la referencia debe estar fijada)</translation>
        </message>
        <message>
            <source>Speed</source>
            <translation>Velocidad</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::LayersPanel</name>
        <message>
            <source>Plot this layer earlier</source>
            <translation>Trazar esta capa antes</translation>
        </message>
        <message>
            <source>Plot this layer later</source>
            <translation>Trazar esta capa después</translation>
        </message>
        <message>
            <source>Tool settings of the selected layer</source>
            <translation>Ajustes de herramienta de la capa seleccionada</translation>
        </message>
        <message>
            <source> mm/s</source>
            <translation> mm/s</translation>
        </message>
        <message>
            <source>Profile default</source>
            <translation>Valor del perfil</translation>
        </message>
        <message>
            <source>Pause before this layer (pen change)</source>
            <translation>Pausa antes de esta capa (cambio de pluma)</translation>
        </message>
        <message>
            <source>Draw speed:</source>
            <translation>Velocidad de dibujo:</translation>
        </message>
        <message>
            <source>Power / pen S:</source>
            <translation>Potencia / S de pluma:</translation>
        </message>
        <message numerus="yes">
            <source>%n path(s)</source>
            <translation>
                <numerusform>%n trazo</numerusform>
                <numerusform>%n trazos</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>%n point(s)</source>
            <translation>
                <numerusform>%n punto</numerusform>
                <numerusform>%n puntos</numerusform>
            </translation>
        </message>
        <message>
            <source>Fill of the selected layer</source>
            <translation>Relleno de la capa seleccionada</translation>
        </message>
        <message>
            <source>Outline</source>
            <translation>Contorno</translation>
        </message>
        <message>
            <source>Hatch</source>
            <translation>Rayado</translation>
        </message>
        <message>
            <source>None</source>
            <translation>Ninguno</translation>
        </message>
        <message>
            <source>How the layer's filled shapes are drawn: their outline, parallel hatch lines inside them, or not at all (stroked shapes keep their stroke).</source>
            <translation>Cómo se dibujan las formas rellenas de la capa: su contorno, líneas de rayado paralelas en su interior o nada (las formas con trazo conservan su trazo).</translation>
        </message>
        <message>
            <source> mm</source>
            <translation> mm</translation>
        </message>
        <message>
            <source> °</source>
            <translation> °</translation>
        </message>
        <message>
            <source>Crosshatch</source>
            <translation>Rayado cruzado</translation>
        </message>
        <message>
            <source>Fill:</source>
            <translation>Relleno:</translation>
        </message>
        <message>
            <source>Hatch spacing:</source>
            <translation>Separación del rayado:</translation>
        </message>
        <message>
            <source>Hatch angle:</source>
            <translation>Ángulo del rayado:</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::MachineBanner</name>
        <message>
            <source>Reset</source>
            <translation>Reiniciar</translation>
        </message>
        <message>
            <source>Soft reset (Ctrl-X): stops everything; the machine keeps its position unless it was moving.</source>
            <translation>Reinicio suave (Ctrl-X): detiene todo; la máquina conserva su posición salvo que se estuviera moviendo.</translation>
        </message>
        <message>
            <source>Unlock ($X)</source>
            <translation>Desbloquear ($X)</translation>
        </message>
        <message>
            <source>Leave the alarm state without homing. Only when you know the machine stands where the studio shows it.</source>
            <translation>Salir del estado de alarma sin buscar el origen. Solo si sabes que la máquina está donde la muestra el estudio.</translation>
        </message>
        <message>
            <source>Dismiss</source>
            <translation>Cerrar</translation>
        </message>
        <message>
            <source>Alarm %1: the machine stopped</source>
            <translation>Alarma %1: la máquina se ha detenido</translation>
        </message>
        <message>
            <source>Alarm: the machine is locked</source>
            <translation>Alarma: la máquina está bloqueada</translation>
        </message>
        <message>
            <source>Error %1: a command was rejected</source>
            <translation>Error %1: se rechazó una orden</translation>
        </message>
        <message>
            <source>The board waits for a reset first: press Reset, then Unlock.</source>
            <translation>La placa espera primero un reinicio: pulsa Reiniciar y luego Desbloquear.</translation>
        </message>
        <message>
            <source>Home ($H)</source>
            <translation>Origen ($H)</translation>
        </message>
        <message>
            <source>Set reference pose</source>
            <translation>Fijar pose de referencia</translation>
        </message>
        <message>
            <source>Run the homing cycle; the machine moves to its switches.</source>
            <translation>Ejecutar la búsqueda de origen; la máquina se mueve hasta sus finales de carrera.</translation>
        </message>
        <message>
            <source>Declare that the machine now stands at the profile's home pose (G10 L20).</source>
            <translation>Declarar que la máquina está ahora en la pose de origen del perfil (G10 L20).</translation>
        </message>
        <message>
            <source>Position unknown: nothing moves until it is set</source>
            <translation>Posición desconocida: nada se mueve hasta fijarla</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::MachineDialogs</name>
        <message>
            <source>Set the reference pose?

The studio will take the machine's current position to be the home pose of "%1": motor 1 at %2°, motor 2 at %3°. Every later move is computed from it.

Confirm only if the arms stand exactly in that pose now. If they stand elsewhere, moves will land in the wrong place and can drive the arms into each other or into the base.</source>
            <translation>¿Fijar la pose de referencia?

El estudio tomará la posición actual de la máquina como la posición de inicio de "%1": motor 1 a %2°, motor 2 a %3°. Todos los movimientos posteriores se calculan a partir de ella.

Confirme solo si los brazos están ahora exactamente en esa pose. Si están en otro sitio, los movimientos acabarán en el lugar equivocado y pueden hacer chocar los brazos entre sí o con la base.</translation>
        </message>
        <message>
            <source>Set reference pose</source>
            <translation>Fijar pose de referencia</translation>
        </message>
        <message>
            <source>The arms stand in the home pose: set it</source>
            <translation>Los brazos están en la posición de inicio: fijarla</translation>
        </message>
        <message>
            <source>Cancel</source>
            <translation>Cancelar</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::MachinePanel</name>
        <message>
            <source>Idle</source>
            <translation>En reposo</translation>
        </message>
        <message>
            <source>Running</source>
            <translation>En marcha</translation>
        </message>
        <message>
            <source>On hold</source>
            <translation>En pausa</translation>
        </message>
        <message>
            <source>Jogging</source>
            <translation>Moviendo</translation>
        </message>
        <message>
            <source>Alarm</source>
            <translation>Alarma</translation>
        </message>
        <message>
            <source>Door open</source>
            <translation>Puerta abierta</translation>
        </message>
        <message>
            <source>Check mode</source>
            <translation>Modo de prueba</translation>
        </message>
        <message>
            <source>Homing</source>
            <translation>Buscando origen</translation>
        </message>
        <message>
            <source>Sleeping</source>
            <translation>En suspensión</translation>
        </message>
        <message>
            <source>Unknown</source>
            <translation>Desconocido</translation>
        </message>
        <message>
            <source>Refresh</source>
            <translation>Actualizar</translation>
        </message>
        <message>
            <source>List the serial ports again</source>
            <translation>Volver a listar los puertos serie</translation>
        </message>
        <message>
            <source>Connect</source>
            <translation>Conectar</translation>
        </message>
        <message>
            <source>Disconnect</source>
            <translation>Desconectar</translation>
        </message>
        <message>
            <source>Baud</source>
            <translation>Baudios</translation>
        </message>
        <message>
            <source>Connection</source>
            <translation>Conexión</translation>
        </message>
        <message>
            <source>Status</source>
            <translation>Estado</translation>
        </message>
        <message>
            <source>State</source>
            <translation>Estado</translation>
        </message>
        <message>
            <source>Pen (X, Y)</source>
            <translation>Pluma (X, Y)</translation>
        </message>
        <message>
            <source>Motors (θ1, θ2)</source>
            <translation>Motores (θ1, θ2)</translation>
        </message>
        <message>
            <source>Buffers</source>
            <translation>Búferes</translation>
        </message>
        <message>
            <source>Simulated machine (built in)</source>
            <translation>Máquina simulada (integrada)</translation>
        </message>
        <message>
            <source>Cannot connect</source>
            <translation>No se puede conectar</translation>
        </message>
        <message>
            <source>Connected to %1</source>
            <translation>Conectado a %1</translation>
        </message>
        <message>
            <source>Not connected</source>
            <translation>Sin conexión</translation>
        </message>
        <message>
            <source>Offline</source>
            <translation>Desconectado</translation>
        </message>
        <message>
            <source>%1, %2 mm</source>
            <translation>%1, %2 mm</translation>
        </message>
        <message>
            <source>%1°, %2°</source>
            <translation>%1°, %2°</translation>
        </message>
        <message>
            <source>planner %1 of %2 blocks free, RX %3 of %4 bytes free</source>
            <translation>planificador: %1 de %2 bloques libres, RX: %3 de %4 bytes libres</translation>
        </message>
        <message>
            <source>Pen</source>
            <translation>Pluma</translation>
        </message>
        <message>
            <source>Review and write...</source>
            <translation>Revisar y escribir...</translation>
        </message>
        <message>
            <source>Compare the board's settings with the profile and write the differences (a backup is saved first)</source>
            <translation>Comparar los ajustes de la placa con el perfil y escribir las diferencias (antes se guarda una copia de seguridad)</translation>
        </message>
        <message>
            <source>No answer from the machine</source>
            <translation>La máquina no responde</translation>
        </message>
        <message>
            <source>Connecting to %1: waiting for the board to answer...</source>
            <translation>Conectando a %1: esperando respuesta de la placa...</translation>
        </message>
        <message>
            <source>up</source>
            <translation>arriba</translation>
        </message>
        <message>
            <source>down (drawing)</source>
            <translation>abajo (dibujando)</translation>
        </message>
        <message>
            <source>not known yet</source>
            <translation>aún desconocido</translation>
        </message>
        <message>
            <source>unknown (set the reference pose)</source>
            <translation>desconocida (fije la pose de referencia)</translation>
        </message>
        <message>
            <source>Cannot open %1.</source>
            <translation>No se puede abrir %1.</translation>
        </message>
    </context>
    <context>
        <name>fivebar::session::MachineSession</name>
        <message>
            <source>No job is planned: open a drawing and let it plan first.</source>
            <translation>No hay ningún trabajo planificado: abre primero un dibujo y deja que se planifique.</translation>
        </message>
        <message>
            <source>No checked frame of the job: %1</source>
            <translation>No hay un contorno comprobado del trabajo: %1</translation>
        </message>
        <message>
            <source>The frame was not sent (see the console).</source>
            <translation>El contorno no se ha enviado (mira la consola).</translation>
        </message>
        <message>
            <source>Frame: the job's outline, %1 mm, pen up</source>
            <translation>Contorno: el contorno del trabajo, %1 mm, bolígrafo levantado</translation>
        </message>
        <message>
            <source>Cannot open %1.</source>
            <translation>No se puede abrir %1.</translation>
        </message>
        <message>
            <source>Connected to %1.</source>
            <translation>Conectado a %1.</translation>
        </message>
        <message>
            <source>Disconnected.</source>
            <translation>Desconectado.</translation>
        </message>
        <message>
            <source>Not connected: %1 was not sent.</source>
            <translation>Sin conexión: %1 no se envió.</translation>
        </message>
        <message>
            <source>Not sent (%1): %2</source>
            <translation>No enviado (%1): %2</translation>
        </message>
        <message>
            <source>A job is running: %1 was not sent.</source>
            <translation>Hay un trabajo en curso: %1 no se envió.</translation>
        </message>
        <message>
            <source>Jog refused: the machine is not idle, not connected or a job is running.</source>
            <translation>Movimiento rechazado: la máquina no está en reposo, no está conectada o hay un trabajo en curso.</translation>
        </message>
        <message>
            <source>[soft reset]</source>
            <translation>[reinicio suave]</translation>
        </message>
        <message>
            <source>[feed hold]</source>
            <translation>[pausa de avance]</translation>
        </message>
        <message>
            <source>[cycle start]</source>
            <translation>[inicio de ciclo]</translation>
        </message>
        <message>
            <source>%1 was rejected: %2</source>
            <translation>%1 fue rechazado: %2</translation>
        </message>
        <message>
            <source>The machine is locked (alarm state). Unlock it with $X or home it with $H once you know where it stands.</source>
            <translation>La máquina está bloqueada (estado de alarma). Desbloquéala con $X o busca su origen con $H cuando sepas dónde está.</translation>
        </message>
        <message>
            <source>The board reset (Grbl %1).</source>
            <translation>La placa se ha reiniciado (Grbl %1).</translation>
        </message>
        <message>
            <source>Connection lost: %1</source>
            <translation>Conexión perdida: %1</translation>
        </message>
        <message>
            <source>the simulated machine</source>
            <translation>la máquina simulada</translation>
        </message>
        <message>
            <source>set the reference pose (Machine panel) or home the machine</source>
            <translation>fije la pose de referencia (panel Máquina) o haga el homing de la máquina</translation>
        </message>
        <message>
            <source>%1 at %2 baud</source>
            <translation>%1 a %2 baudios</translation>
        </message>
        <message>
            <source>Opened %1; waiting for the board to answer...</source>
            <translation>%1 abierto; esperando respuesta de la placa...</translation>
        </message>
        <message>
            <source>No GRBL board answered on %1 within %2 s. Check that the port is the machine's, that the baud rate matches its firmware (GRBL 1.1: usually 115200) and that it is powered.</source>
            <translation>Ninguna placa GRBL respondió en %1 en %2 s. Compruebe que el puerto es el de la máquina, que la velocidad en baudios coincide con su firmware (GRBL 1.1: normalmente 115200) y que está encendida.</translation>
        </message>
        <message>
            <source>Not sent: %1</source>
            <translation>No enviado: %1</translation>
        </message>
        <message>
            <source>Unchecked: %1</source>
            <translation>Sin comprobar: %1</translation>
        </message>
        <message>
            <source>The machine's position is not known yet (no status report with its work position): wait a moment, or set the reference pose.</source>
            <translation>La posición de la máquina aún no se conoce (no hay informe de estado con su posición de trabajo): espere un momento o fije la pose de referencia.</translation>
        </message>
        <message>
            <source>The machine is still moving or busy: send a move when it stands still (Idle), so it can be checked from where the machine really is.</source>
            <translation>La máquina aún se mueve o está ocupada: envíe el movimiento cuando esté parada (Idle), para poder comprobarlo desde donde está realmente.</translation>
        </message>
        <message>
            <source>Console lines are sent UNCHECKED from now on.</source>
            <translation>A partir de ahora las líneas de consola se envían SIN COMPROBAR.</translation>
        </message>
        <message>
            <source>Console lines are checked again.</source>
            <translation>Las líneas de consola vuelven a comprobarse.</translation>
        </message>
        <message>
            <source>The machine must be connected, idle and its position known.</source>
            <translation>La máquina debe estar conectada, inactiva y con su posición conocida.</translation>
        </message>
        <message>
            <source>The profile's home pose does not close the linkage.</source>
            <translation>La posición de inicio del perfil no cierra el mecanismo.</translation>
        </message>
        <message>
            <source>No checked move to the home pose: %1</source>
            <translation>No hay movimiento comprobado a la posición de inicio: %1</translation>
        </message>
        <message>
            <source>The move was not sent (see the console).</source>
            <translation>El movimiento no se envió (véase la consola).</translation>
        </message>
        <message>
            <source>choose a target inside the workspace</source>
            <translation>elija un objetivo dentro del espacio de trabajo</translation>
        </message>
        <message>
            <source>Move not sent: %1</source>
            <translation>Movimiento no enviado: %1</translation>
        </message>
        <message>
            <source>Home the machine (Home), or put the arms in the home pose and press Set reference pose.</source>
            <translation>Haga el homing (Home), o ponga los brazos en la pose de inicio y pulse Fijar pose de referencia.</translation>
        </message>
        <message>
            <source>Put the arms in the home pose by hand and press Set reference pose.</source>
            <translation>Ponga los brazos a mano en la pose de inicio y pulse Fijar pose de referencia.</translation>
        </message>
        <message>
            <source>Reading where the machine stands...</source>
            <translation>Leyendo dónde está la máquina…</translation>
        </message>
        <message>
            <source>The machine's position is not known: this board has not been referenced from this computer yet. %1</source>
            <translation>La posición de la máquina no se conoce: esta placa aún no se ha referenciado desde este ordenador. %1</translation>
        </message>
        <message>
            <source>The machine's position is not known: the board was powered up or reset since it was last seen, so the position it reports says nothing about where the arms stand. %1</source>
            <translation>La posición de la máquina no se conoce: la placa se encendió o se reinició desde la última vez, así que la posición que indica no dice nada de dónde están los brazos. %1</translation>
        </message>
        <message>
            <source>The machine's position is not known: it was reset or stopped hard while moving, and the motors may have lost steps. %1</source>
            <translation>La posición de la máquina no se conoce: se reinició o se detuvo en seco mientras se movía y los motores pueden haber perdido pasos. %1</translation>
        </message>
        <message>
            <source>The machine's position is not known: the homing cycle moved the arms and did not finish. %1</source>
            <translation>La posición de la máquina no se conoce: el ciclo de homing movió los brazos y no terminó. %1</translation>
        </message>
        <message>
            <source>The machine's position is not known: it moved while no program watched it (a job cut off by a crash, a closed connection or another program). %1</source>
            <translation>La posición de la máquina no se conoce: se movió sin que ningún programa la vigilara (un trabajo cortado por un fallo, una conexión cerrada u otro programa). %1</translation>
        </message>
        <message>
            <source>Not connected.</source>
            <translation>No conectada.</translation>
        </message>
        <message>
            <source>Moves are sent although the board's settings differ from the profile (expert override).</source>
            <translation>Los movimientos se envían aunque los ajustes de la placa difieren del perfil (modo experto).</translation>
        </message>
        <message>
            <source>The machine is not connected.</source>
            <translation>La máquina no está conectada.</translation>
        </message>
        <message>
            <source>A job is running.</source>
            <translation>Hay un trabajo en marcha.</translation>
        </message>
        <message>
            <source>The board's settings %1 differ from the profile, so the machine would not move as planned: write the profile's settings (Machine settings...) first.</source>
            <translation>Los ajustes %1 de la placa difieren del perfil, así que la máquina no se movería como está previsto: escriba primero los ajustes del perfil (Ajustes de la máquina…).</translation>
        </message>
        <message>
            <source>The machine is not idle.</source>
            <translation>La máquina no está en reposo.</translation>
        </message>
        <message>
            <source>Jog refused: %1</source>
            <translation>Movimiento rechazado: %1</translation>
        </message>
        <message>
            <source>[feed override 100 %]</source>
            <translation>[ajuste de avance 100 %]</translation>
        </message>
        <message>
            <source>[feed override +10 %]</source>
            <translation>[ajuste de avance +10 %]</translation>
        </message>
        <message>
            <source>[feed override -10 %]</source>
            <translation>[ajuste de avance -10 %]</translation>
        </message>
        <message>
            <source>[feed override +1 %]</source>
            <translation>[ajuste de avance +1 %]</translation>
        </message>
        <message>
            <source>[feed override -1 %]</source>
            <translation>[ajuste de avance -1 %]</translation>
        </message>
        <message>
            <source>[rapid override 100 %]</source>
            <translation>[ajuste de rápidos 100 %]</translation>
        </message>
        <message>
            <source>[rapid override 50 %]</source>
            <translation>[ajuste de rápidos 50 %]</translation>
        </message>
        <message>
            <source>[rapid override 25 %]</source>
            <translation>[ajuste de rápidos 25 %]</translation>
        </message>
        <message numerus="yes">
            <source>%1 (jog in %n checked move(s))</source>
            <translation>
                <numerusform>%1 (movimiento en %n paso comprobado)</numerusform>
                <numerusform>%1 (movimiento en %n pasos comprobados)</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::MachineSettingsDialog</name>
        <message>
            <source>Machine settings</source>
            <translation>Ajustes de la máquina</translation>
        </message>
        <message>
            <source>The board's GRBL settings next to the values the machine profile needs. Writing saves a backup of the board's settings first.</source>
            <translation>Los ajustes GRBL de la placa junto a los valores que necesita el perfil de máquina. Antes de escribir se guarda una copia de seguridad de los ajustes de la placa.</translation>
        </message>
        <message>
            <source>Setting</source>
            <translation>Ajuste</translation>
        </message>
        <message>
            <source>Board</source>
            <translation>Placa</translation>
        </message>
        <message>
            <source>Profile</source>
            <translation>Perfil</translation>
        </message>
        <message>
            <source>Differs</source>
            <translation>Difiere</translation>
        </message>
        <message>
            <source>Read from board</source>
            <translation>Leer de la placa</translation>
        </message>
        <message>
            <source>Write differences...</source>
            <translation>Escribir diferencias…</translation>
        </message>
        <message>
            <source>Close</source>
            <translation>Cerrar</translation>
        </message>
        <message>
            <source>The machine was disconnected.</source>
            <translation>La máquina se ha desconectado.</translation>
        </message>
        <message>
            <source>Connect the machine first.</source>
            <translation>Conecta primero la máquina.</translation>
        </message>
        <message>
            <source>A job is running.</source>
            <translation>Hay un trabajo en curso.</translation>
        </message>
        <message>
            <source>Still talking to the board.</source>
            <translation>Aún comunicando con la placa.</translation>
        </message>
        <message>
            <source>The machine must be idle (or in alarm) to change settings.</source>
            <translation>La máquina debe estar en reposo (o en alarma) para cambiar los ajustes.</translation>
        </message>
        <message>
            <source>Reading the board's settings...</source>
            <translation>Leyendo los ajustes de la placa…</translation>
        </message>
        <message>
            <source>Nothing to write: read the board's settings first.</source>
            <translation>Nada que escribir: lee primero los ajustes de la placa.</translation>
        </message>
        <message>
            <source>Write settings</source>
            <translation>Escribir ajustes</translation>
        </message>
        <message numerus="yes">
            <source>Write %n setting(s) to the board? Its current settings are saved to a backup file first.</source>
            <translation>
                <numerusform>¿Escribir %n ajuste en la placa? Sus ajustes actuales se guardan antes en un archivo de copia de seguridad.</numerusform>
                <numerusform>¿Escribir %n ajustes en la placa? Sus ajustes actuales se guardan antes en un archivo de copia de seguridad.</numerusform>
            </translation>
        </message>
        <message>
            <source>The board's settings match the profile.</source>
            <translation>Los ajustes de la placa coinciden con el perfil.</translation>
        </message>
        <message numerus="yes">
            <source>%n setting(s) differ from the profile.</source>
            <translation>
                <numerusform>%n ajuste difiere del perfil.</numerusform>
                <numerusform>%n ajustes difieren del perfil.</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>%n setting(s) written. Backup of the previous settings: %1</source>
            <translation>
                <numerusform>%n ajuste escrito. Copia de seguridad de los ajustes anteriores: %1</numerusform>
                <numerusform>%n ajustes escritos. Copia de seguridad de los ajustes anteriores: %1</numerusform>
            </translation>
        </message>
        <message>
            <source>Writing settings one at a time... Backup: %1</source>
            <translation>Escribiendo los ajustes de uno en uno… Copia de seguridad: %1</translation>
        </message>
        <message>
            <source>Failed: %1</source>
            <translation>Error: %1</translation>
        </message>
        <message>
            <source>yes</source>
            <translation>sí</translation>
        </message>
        <message>
            <source>Meaning</source>
            <translation>Significado</translation>
        </message>
        <message>
            <source>Unit</source>
            <translation>Unidad</translation>
        </message>
        <message>
            <source>(not a GRBL 1.1h setting)</source>
            <translation>(no es un ajuste de GRBL 1.1h)</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::MachinePanels</name>
        <message>
            <source>Machine</source>
            <translation>Máquina</translation>
        </message>
        <message>
            <source>Run</source>
            <translation>Ejecución</translation>
        </message>
        <message>
            <source>Jog</source>
            <translation>Mover</translation>
        </message>
        <message>
            <source>Console</source>
            <translation>Consola</translation>
        </message>
        <message>
            <source>Machine profile</source>
            <translation>Perfil</translation>
        </message>
        <message>
            <source>Machine &amp;settings...</source>
            <translation>&amp;Ajustes de la máquina…</translation>
        </message>
        <message>
            <source>A job is running</source>
            <translation>Hay un trabajo en curso</translation>
        </message>
        <message>
            <source>The machine is drawing "%1". Quitting the studio would leave it without its stream of lines.

Hold, stop and quit: the machine stops cleanly and the progress is saved, so you can resume later.</source>
            <translation>La máquina está dibujando "%1". Salir del estudio la dejaría sin su flujo de líneas.

Pausar, detener y salir: la máquina se detiene limpiamente y el progreso se guarda para que pueda reanudarlo más tarde.</translation>
        </message>
        <message>
            <source>Hold, stop and quit</source>
            <translation>Pausar, detener y salir</translation>
        </message>
        <message>
            <source>Keep running</source>
            <translation>Seguir ejecutando</translation>
        </message>
        <message>
            <source>The job has ended</source>
            <translation>El trabajo ha terminado</translation>
        </message>
        <message>
            <source>The job "%1" has ended. Quit FiveBar Studio?</source>
            <translation>El trabajo «%1» ha terminado. ¿Salir de FiveBar Studio?</translation>
        </message>
        <message>
            <source>Quit</source>
            <translation>Salir</translation>
        </message>
        <message>
            <source>Cancel</source>
            <translation>Cancelar</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::ModePanel</name>
        <message>
            <source>Working mode</source>
            <translation>Modo de trabajo</translation>
        </message>
        <message>
            <source>Auto</source>
            <translation>Auto</translation>
        </message>
        <message>
            <source>Let the planner pick the feasible mode with the largest margin</source>
            <translation>Dejar que el planificador elija el modo factible con mayor margen</translation>
        </message>
        <message>
            <source>Elbows %1 (arm 1 %2, arm 2 %3)</source>
            <translation>Codos %1 (brazo 1 %2, brazo 2 %3)</translation>
        </message>
        <message>
            <source>out</source>
            <translation>fuera</translation>
        </message>
        <message>
            <source>in</source>
            <translation>dentro</translation>
        </message>
        <message>
            <source>Overlays</source>
            <translation>Capas superpuestas</translation>
        </message>
        <message>
            <source>Reachable and singularity-free regions</source>
            <translation>Zonas alcanzables y sin singularidades</translation>
        </message>
        <message>
            <source>Type II singularity curves</source>
            <translation>Curvas de singularidad de tipo II</translation>
        </message>
        <message>
            <source>Largest singularity-free rectangle</source>
            <translation>Mayor rectángulo sin singularidades</translation>
        </message>
        <message>
            <source>Workspace legend</source>
            <translation>Leyenda del espacio de trabajo</translation>
        </message>
        <message>
            <source>None</source>
            <translation>Ninguno</translation>
        </message>
        <message>
            <source>Transmission angle</source>
            <translation>Ángulo de transmisión</translation>
        </message>
        <message>
            <source>Conditioning</source>
            <translation>Condicionamiento</translation>
        </message>
        <message>
            <source>Resolution (mm per step)</source>
            <translation>Resolución (mm por paso)</translation>
        </message>
        <message>
            <source>Map:</source>
            <translation>Mapa:</translation>
        </message>
        <message>
            <source>Auto picked %1.</source>
            <translation>Auto eligió %1.</translation>
        </message>
        <message>
            <source>Auto: no mode draws the whole job; showing %1.</source>
            <translation>Auto: ningún modo dibuja todo el trabajo; se muestra %1.</translation>
        </message>
        <message>
            <source>Showing the workspace of %1.</source>
            <translation>Se muestra el espacio de trabajo de %1.</translation>
        </message>
        <message>
            <source>Smallest singularity margin: %1 deg.</source>
            <translation>Menor margen de singularidad: %1°.</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::ParetoPlot</name>
        <message>
            <source>Footprint (cm²)</source>
            <translation>Superficie ocupada (cm²)</translation>
        </message>
        <message>
            <source>Worst condition number</source>
            <translation>Peor número de condición</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::PlacementPanel</name>
        <message>
            <source> mm</source>
            <translation> mm</translation>
        </message>
        <message>
            <source> deg</source>
            <translation> °</translation>
        </message>
        <message>
            <source> %</source>
            <translation> %</translation>
        </message>
        <message>
            <source>Centre X:</source>
            <translation>Centro X:</translation>
        </message>
        <message>
            <source>Centre Y:</source>
            <translation>Centro Y:</translation>
        </message>
        <message>
            <source>Rotation:</source>
            <translation>Rotación:</translation>
        </message>
        <message>
            <source>Scale:</source>
            <translation>Escala:</translation>
        </message>
        <message>
            <source>Fit to workspace</source>
            <translation>Ajustar al espacio</translation>
        </message>
        <message>
            <source>Keep aspect ratio</source>
            <translation>Mantener proporción</translation>
        </message>
        <message>
            <source>Width:</source>
            <translation>Ancho:</translation>
        </message>
        <message>
            <source>Height:</source>
            <translation>Alto:</translation>
        </message>
        <message>
            <source>Actual size</source>
            <translation>Tamaño real</translation>
        </message>
        <message>
            <source>Draw the drawing at its true size (100 %)</source>
            <translation>Dibujar el dibujo a su tamaño real (100 %)</translation>
        </message>
        <message>
            <source>Scale the drawing to fill the largest singularity-free rectangle</source>
            <translation>Escalar el dibujo para llenar el mayor rectángulo sin singularidades</translation>
        </message>
        <message>
            <source>No singularity-free area to fit the drawing into.</source>
            <translation>No hay ninguna zona sin singularidades donde ajustar el dibujo.</translation>
        </message>
        <message>
            <source>Fitted: %1 %</source>
            <translation>Ajustado: %1 %</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::PreviewPanel</name>
        <message>
            <source>%1 % of what this machine can do</source>
            <translation>%1 % del máximo posible</translation>
        </message>
        <message>
            <source>%1 s</source>
            <translation>%1 s</translation>
        </message>
        <message>
            <source>%1 h %2 min</source>
            <translation>%1 h %2 min</translation>
        </message>
        <message>
            <source>%1 min %2 s</source>
            <translation>%1 min %2 s</translation>
        </message>
        <message>
            <source>Show</source>
            <translation>Mostrar</translation>
        </message>
        <message>
            <source>Colour pen-down moves by speed</source>
            <translation>Colorear los trazos según la velocidad</translation>
        </message>
        <message>
            <source>Pen-up moves (grey)</source>
            <translation>Movimientos con pluma subida (gris)</translation>
        </message>
        <message>
            <source>Drawing order</source>
            <translation>Orden de dibujo</translation>
        </message>
        <message>
            <source>Pre-flight problems (click to show):</source>
            <translation>Problemas previos (clic para ver):</translation>
        </message>
        <message>
            <source>Moves shown: %1 of %2</source>
            <translation>Movimientos mostrados: %1 de %2</translation>
        </message>
        <message>
            <source>Planning...</source>
            <translation>Planificando…</translation>
        </message>
        <message>
            <source>Planned.</source>
            <translation>Planificado.</translation>
        </message>
        <message>
            <source>Open a drawing to plan a job.</source>
            <translation>Abre un dibujo para planificar un trabajo.</translation>
        </message>
        <message>
            <source>Working mode: &lt;b&gt;%1&lt;/b&gt;</source>
            <translation>Modo de trabajo: &lt;b&gt;%1&lt;/b&gt;</translation>
        </message>
        <message>
            <source>No problems: every move is reachable and safe.</source>
            <translation>Sin problemas: todos los movimientos son alcanzables y seguros.</translation>
        </message>
        <message>
            <source>What to do: %1</source>
            <translation>Qué hacer: %1</translation>
        </message>
        <message>
            <source>&lt;table&gt;&lt;tr&gt;&lt;td&gt;Working mode:&lt;/td&gt;&lt;td&gt;&lt;b&gt;%1&lt;/b&gt;&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Estimated time:&lt;/td&gt;&lt;td&gt;&lt;b&gt;%2&lt;/b&gt;&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;/td&gt;&lt;td&gt;%8&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Pen down:&lt;/td&gt;&lt;td&gt;%3 mm&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Pen up:&lt;/td&gt;&lt;td&gt;%4 mm&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Segments:&lt;/td&gt;&lt;td&gt;%5&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Max deviation:&lt;/td&gt;&lt;td&gt;%6 mm&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Singularity margin:&lt;/td&gt;&lt;td&gt;%7 deg&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</source>
            <translation>&lt;table&gt;&lt;tr&gt;&lt;td&gt;Modo de trabajo:&lt;/td&gt;&lt;td&gt;&lt;b&gt;%1&lt;/b&gt;&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Tiempo estimado:&lt;/td&gt;&lt;td&gt;&lt;b&gt;%2&lt;/b&gt;&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;/td&gt;&lt;td&gt;%8&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Pluma bajada:&lt;/td&gt;&lt;td&gt;%3 mm&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Pluma subida:&lt;/td&gt;&lt;td&gt;%4 mm&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Segmentos:&lt;/td&gt;&lt;td&gt;%5&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Desviación máx.:&lt;/td&gt;&lt;td&gt;%6 mm&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Margen de singularidad:&lt;/td&gt;&lt;td&gt;%7°&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</translation>
        </message>
        <message>
            <source>; </source>
            <translation>; </translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::ProfileEditor</name>
        <message>
            <source>Load preset</source>
            <translation>Cargar preajuste</translation>
        </message>
        <message>
            <source>Import…</source>
            <translation>Importar…</translation>
        </message>
        <message>
            <source>Load a machine profile from a JSON file</source>
            <translation>Cargar un perfil de máquina desde un archivo JSON</translation>
        </message>
        <message>
            <source>Export…</source>
            <translation>Exportar…</translation>
        </message>
        <message>
            <source>Save this machine profile as a JSON file</source>
            <translation>Guardar este perfil de máquina como archivo JSON</translation>
        </message>
        <message>
            <source>Machine</source>
            <translation>Máquina</translation>
        </message>
        <message>
            <source>Name</source>
            <translation>Nombre</translation>
        </message>
        <message>
            <source>Geometry</source>
            <translation>Geometría</translation>
        </message>
        <message>
            <source>Joint limits</source>
            <translation>Límites articulares</translation>
        </message>
        <message>
            <source>Motors</source>
            <translation>Motores</translation>
        </message>
        <message>
            <source>Tool</source>
            <translation>Herramienta</translation>
        </message>
        <message>
            <source>Motion and safety</source>
            <translation>Movimiento y seguridad</translation>
        </message>
        <message>
            <source>Connection and home pose</source>
            <translation>Conexión y pose de origen</translation>
        </message>
        <message>
            <source> mm</source>
            <translation> mm</translation>
        </message>
        <message>
            <source> °</source>
            <translation> °</translation>
        </message>
        <message>
            <source> s</source>
            <translation> s</translation>
        </message>
        <message>
            <source>Limit the motor angles</source>
            <translation>Limitar los ángulos de los motores</translation>
        </message>
        <message>
            <source> °/min</source>
            <translation> °/min</translation>
        </message>
        <message>
            <source> °/s²</source>
            <translation> °/s²</translation>
        </message>
        <message>
            <source>Pen servo (M3 S / M5)</source>
            <translation>Servo de pluma (M3 S / M5)</translation>
        </message>
        <message>
            <source>Z axis</source>
            <translation>Eje Z</translation>
        </message>
        <message>
            <source>Laser (M4 S / M5)</source>
            <translation>Láser (M4 S / M5)</translation>
        </message>
        <message>
            <source> mm/min</source>
            <translation> mm/min</translation>
        </message>
        <message>
            <source>Working mode (built)</source>
            <translation>Modo de trabajo (montaje)</translation>
        </message>
        <message>
            <source>Assembly mode</source>
            <translation>Modo de ensamblaje</translation>
        </message>
        <message>
            <source> mm/s</source>
            <translation> mm/s</translation>
        </message>
        <message>
            <source>The machine has homing switches ($H)</source>
            <translation>Con finales de carrera de origen ($H)</translation>
        </message>
        <message>
            <source>The profile is not applied until these problems are fixed.</source>
            <translation>El perfil no se aplica hasta que se corrijan estos problemas.</translation>
        </message>
        <message>
            <source>%1 cannot be used:
%2</source>
            <translation>No se puede usar %1:
%2</translation>
        </message>
        <message>
            <source>Fix the profile's problems before exporting it.</source>
            <translation>Corrige los problemas del perfil antes de exportarlo.</translation>
        </message>
        <message>
            <source>Import machine profile</source>
            <translation>Importar perfil de máquina</translation>
        </message>
        <message>
            <source>Machine profiles (*.json)</source>
            <translation>Perfiles de máquina (*.json)</translation>
        </message>
        <message>
            <source>Import failed</source>
            <translation>Error de importación</translation>
        </message>
        <message>
            <source>Export machine profile</source>
            <translation>Exportar perfil de máquina</translation>
        </message>
        <message>
            <source>Export failed</source>
            <translation>Error de exportación</translation>
        </message>
        <message>
            <source> steps/°</source>
            <translation> pasos/°</translation>
        </message>
        <message>
            <source> baud</source>
            <translation> baudios</translation>
        </message>
    </context>
    <context>
        <name>ProfileField</name>
        <message>
            <source>Driving link a1</source>
            <translation>Brazo motor a1</translation>
        </message>
        <message>
            <source>Floating link b1</source>
            <translation>Brazo libre b1</translation>
        </message>
        <message>
            <source>Driving link a2</source>
            <translation>Brazo motor a2</translation>
        </message>
        <message>
            <source>Floating link b2</source>
            <translation>Brazo libre b2</translation>
        </message>
        <message>
            <source>Motor distance w</source>
            <translation>Distancia entre motores w</translation>
        </message>
        <message>
            <source>θ1 minimum</source>
            <translation>θ1 mínimo</translation>
        </message>
        <message>
            <source>θ1 maximum</source>
            <translation>θ1 máximo</translation>
        </message>
        <message>
            <source>θ2 minimum</source>
            <translation>θ2 mínimo</translation>
        </message>
        <message>
            <source>θ2 maximum</source>
            <translation>θ2 máximo</translation>
        </message>
        <message>
            <source>Motor 1 steps per degree</source>
            <translation>Motor 1: pasos por grado</translation>
        </message>
        <message>
            <source>Motor 2 steps per degree</source>
            <translation>Motor 2: pasos por grado</translation>
        </message>
        <message>
            <source>Motor 1 maximum speed</source>
            <translation>Motor 1: velocidad máxima</translation>
        </message>
        <message>
            <source>Motor 2 maximum speed</source>
            <translation>Motor 2: velocidad máxima</translation>
        </message>
        <message>
            <source>Motor 1 acceleration</source>
            <translation>Motor 1: aceleración</translation>
        </message>
        <message>
            <source>Motor 2 acceleration</source>
            <translation>Motor 2: aceleración</translation>
        </message>
        <message>
            <source>Junction deviation</source>
            <translation>Desviación de unión</translation>
        </message>
        <message>
            <source>Pen up S value</source>
            <translation>Valor S pluma subida</translation>
        </message>
        <message>
            <source>Pen down S value</source>
            <translation>Valor S pluma bajada</translation>
        </message>
        <message>
            <source>Pen up delay</source>
            <translation>Espera pluma subida</translation>
        </message>
        <message>
            <source>Pen down delay</source>
            <translation>Espera pluma bajada</translation>
        </message>
        <message>
            <source>Z up</source>
            <translation>Z arriba</translation>
        </message>
        <message>
            <source>Z down</source>
            <translation>Z abajo</translation>
        </message>
        <message>
            <source>Z feed</source>
            <translation>Avance Z</translation>
        </message>
        <message>
            <source>Laser power S value</source>
            <translation>Valor S de potencia láser</translation>
        </message>
        <message>
            <source>Drawing speed</source>
            <translation>Velocidad de dibujo</translation>
        </message>
        <message>
            <source>Travel speed</source>
            <translation>Velocidad de desplazamiento</translation>
        </message>
        <message>
            <source>Type II singularity margin</source>
            <translation>Margen de singularidad de tipo II</translation>
        </message>
        <message>
            <source>Type I singularity margin</source>
            <translation>Margen de singularidad de tipo I</translation>
        </message>
        <message>
            <source>Baud rate</source>
            <translation>Velocidad en baudios</translation>
        </message>
        <message>
            <source>Home θ1</source>
            <translation>Origen θ1</translation>
        </message>
        <message>
            <source>Home θ2</source>
            <translation>Origen θ2</translation>
        </message>
        <message>
            <source>Calibration format version</source>
            <translation>Versión del formato de calibración</translation>
        </message>
        <message>
            <source>Held-out marks</source>
            <translation>Marcas reservadas</translation>
        </message>
        <message>
            <source>Largest residual of the fit</source>
            <translation>Mayor residuo del ajuste</translation>
        </message>
        <message>
            <source>Marks used by the fit</source>
            <translation>Marcas usadas por el ajuste</translation>
        </message>
        <message>
            <source>Motor 1 backlash</source>
            <translation>Holgura del motor 1</translation>
        </message>
        <message>
            <source>Motor 1 zero offset</source>
            <translation>Desfase del cero del motor 1</translation>
        </message>
        <message>
            <source>Motor 2 backlash</source>
            <translation>Holgura del motor 2</translation>
        </message>
        <message>
            <source>Motor 2 zero offset</source>
            <translation>Desfase del cero del motor 2</translation>
        </message>
        <message>
            <source>Pen offset across b1</source>
            <translation>Desplazamiento del bolígrafo transversal a b1</translation>
        </message>
        <message>
            <source>Pen offset along b1</source>
            <translation>Desplazamiento del bolígrafo a lo largo de b1</translation>
        </message>
        <message>
            <source>RMS error on held-out marks</source>
            <translation>Error RMS en las marcas reservadas</translation>
        </message>
        <message>
            <source>RMS residual of the fit</source>
            <translation>Residuo RMS del ajuste</translation>
        </message>
    </context>
    <context>
        <name>fivebar::session::RunController</name>
        <message>
            <source>Not started: the board's soft limits would stop this job with an alarm (ALARM:2): %1. The board checks its travel ($130, $131) in machine coordinates, which the reference pose shifted against the drawing's. Home the machine, or make the board's settings match the profile (Machine settings...), then start again.</source>
            <translation>No iniciado: los límites por software de la placa detendrían este trabajo con una alarma (ALARM:2): %1. La placa comprueba su recorrido ($130, $131) en coordenadas de máquina, que la pose de referencia desplazó respecto a las del dibujo. Haga el homing de la máquina o ajuste la configuración de la placa al perfil (Ajustes de la máquina…) y vuelva a iniciar.</translation>
        </message>
        <message>
            <source>The connection was closed during the run. The progress is saved beside the job: reconnect and resume.</source>
            <translation>La conexión se cerró durante la ejecución. El progreso se guarda junto al trabajo: vuelve a conectar y reanuda.</translation>
        </message>
        <message>
            <source>Cannot start: connect the machine, wait until it is idle, and let the job plan first.</source>
            <translation>No se puede iniciar: conecta la máquina, espera a que esté en reposo y deja que el trabajo se planifique primero.</translation>
        </message>
        <message>
            <source>Cannot create the job folder %1.</source>
            <translation>No se puede crear la carpeta del trabajo %1.</translation>
        </message>
        <message>
            <source>Nothing to resume: there is no saved progress beside %1.</source>
            <translation>Nada que reanudar: no hay progreso guardado junto a %1.</translation>
        </message>
        <message>
            <source>line %1 of %2</source>
            <translation>línea %1 de %2</translation>
        </message>
        <message>
            <source>The run of "%1" was interrupted at %2: %3</source>
            <translation>La ejecución de "%1" se interrumpió en %2: %3</translation>
        </message>
        <message>
            <source>press Resume</source>
            <translation>pulse Reanudar</translation>
        </message>
        <message>
            <source>Resume</source>
            <translation>Reanudar</translation>
        </message>
        <message>
            <source>The machine raised an alarm and the job stopped (the banner in the Machine panel says why). The progress is saved: clear the alarm (Reset, Unlock), check the pen stands where the studio shows it, then press Resume.</source>
            <translation>La máquina lanzó una alarma y el trabajo se detuvo (el aviso del panel Máquina indica por qué). El progreso está guardado: borre la alarma (Reset, Desbloquear), compruebe que la pluma está donde la muestra el estudio y pulse Reanudar.</translation>
        </message>
        <message>
            <source>Resuming "%1"…</source>
            <translation>Reanudando "%1"…</translation>
        </message>
        <message>
            <source>Running "%1"…</source>
            <translation>Ejecutando "%1"…</translation>
        </message>
        <message>
            <source>"%1" is drawn.</source>
            <translation>"%1" está dibujado.</translation>
        </message>
        <message>
            <source>Not started: %1</source>
            <translation>No iniciado: %1</translation>
        </message>
        <message>
            <source>The run of "%1" was interrupted after %2: %3</source>
            <translation>La ejecución de «%1» se interrumpió después de %2: %3</translation>
        </message>
        <message>
            <source>The drawing, its placement, the machine profile or the tolerance changed since, so Resume would draw the old job where the canvas no longer shows it: undo the change to resume, or press Start to draw the new one from the beginning.</source>
            <translation>El dibujo, su colocación, el perfil de la máquina o la tolerancia han cambiado desde entonces, así que Reanudar dibujaría el trabajo antiguo donde el lienzo ya no lo muestra: deshaga el cambio para reanudar, o pulse Iniciar para dibujar el nuevo desde el principio.</translation>
        </message>
        <message>
            <source>Not started: the board's settings differ from the profile. %1 Write the profile's settings (Machine settings...), or choose Start anyway when Start asks.</source>
            <translation>No iniciado: los ajustes de la placa difieren del perfil. %1 Escriba los ajustes del perfil (Ajustes de la máquina…), o elija Iniciar de todos modos cuando Iniciar lo pregunte.</translation>
        </message>
        <message>
            <source>Stopped before the first move: nothing was sent.</source>
            <translation>Detenido antes del primer movimiento: no se envió nada.</translation>
        </message>
        <message>
            <source>Stopped after line %1 of %2; the pen is up and the machine at rest.</source>
            <translation>Detenido después de la línea %1 de %2; el bolígrafo está arriba y la máquina en reposo.</translation>
        </message>
        <message>
            <source>Stopped after line %1 of %2; the pen could not be lifted.</source>
            <translation>Detenido después de la línea %1 de %2; no se pudo levantar el bolígrafo.</translation>
        </message>
        <message>
            <source>The progress is saved: press Resume to continue.</source>
            <translation>El progreso está guardado: pulse Reanudar para continuar.</translation>
        </message>
        <message>
            <source>Stopped after line %1 of %2: %3 The progress is saved: press Resume to continue.</source>
            <translation>Detenido después de la línea %1 de %2: %3 El progreso está guardado: pulse Reanudar para continuar.</translation>
        </message>
        <message>
            <source>Not resumed: the job is not planned yet; wait for the preview.</source>
            <translation>No reanudado: el trabajo aún no está planificado; espere a la vista previa.</translation>
        </message>
        <message>
            <source>Not resumed: the drawing, its placement, the machine profile or the tolerance changed since the run was interrupted, so Resume would draw the old job where the canvas no longer shows it. Undo the change to resume, or press Start to draw the new one from the beginning.</source>
            <translation>No reanudado: el dibujo, su colocación, el perfil de la máquina o la tolerancia han cambiado desde la interrupción, así que Reanudar dibujaría el trabajo antiguo donde el lienzo ya no lo muestra. Deshaga el cambio para reanudar, o pulse Iniciar para dibujar el nuevo desde el principio.</translation>
        </message>
        <message>
            <source>Cannot resume: connect the machine and wait until it is idle.</source>
            <translation>No se puede reanudar: conecte la máquina y espere a que esté en reposo.</translation>
        </message>
        <message>
            <source>Not resumed: %1</source>
            <translation>No reanudado: %1</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::OverrideControls</name>
        <message>
            <source>Overrides</source>
            <translation>Ajustes</translation>
        </message>
        <message>
            <source>The machine scales the job's feed (10 to 200 %) and its rapid moves (25, 50 or 100 %) at once. It never exceeds its maximum rates ($110, $111): a higher feed override stops speeding up where the motors' limit is.</source>
            <translation>La máquina ajusta al instante el avance del trabajo (10 a 200 %) y sus movimientos rápidos (25, 50 o 100 %). Nunca supera sus velocidades máximas ($110, $111): un ajuste de avance mayor deja de acelerar donde está el límite de los motores.</translation>
        </message>
        <message>
            <source>Feed override: pen-down and other G1 moves</source>
            <translation>Ajuste de avance: movimientos con el bolígrafo bajado y otros movimientos G1</translation>
        </message>
        <message>
            <source>Rapid override: G0 travel moves</source>
            <translation>Ajuste de rápidos: desplazamientos G0</translation>
        </message>
        <message>
            <source>Feed</source>
            <translation>Avance</translation>
        </message>
        <message>
            <source>−10 %</source>
            <translation>−10 %</translation>
        </message>
        <message>
            <source>Alt+Down</source>
            <translation>Alt+Down</translation>
        </message>
        <message>
            <source>−1 %</source>
            <translation>−1 %</translation>
        </message>
        <message>
            <source>Alt+Left</source>
            <translation>Alt+Left</translation>
        </message>
        <message>
            <source>100 %</source>
            <translation>100 %</translation>
        </message>
        <message>
            <source>Alt+0</source>
            <translation>Alt+0</translation>
        </message>
        <message>
            <source>+1 %</source>
            <translation>+1 %</translation>
        </message>
        <message>
            <source>Alt+Right</source>
            <translation>Alt+Right</translation>
        </message>
        <message>
            <source>+10 %</source>
            <translation>+10 %</translation>
        </message>
        <message>
            <source>Alt+Up</source>
            <translation>Alt+Up</translation>
        </message>
        <message>
            <source>Rapid</source>
            <translation>Rápido</translation>
        </message>
        <message>
            <source>25 %</source>
            <translation>25 %</translation>
        </message>
        <message>
            <source>Alt+4</source>
            <translation>Alt+4</translation>
        </message>
        <message>
            <source>50 %</source>
            <translation>50 %</translation>
        </message>
        <message>
            <source>Alt+2</source>
            <translation>Alt+2</translation>
        </message>
        <message>
            <source>Alt+1</source>
            <translation>Alt+1</translation>
        </message>
        <message>
            <source>%1 %</source>
            <translation>%1 %</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::RunPanel</name>
        <message>
            <source>Ready</source>
            <translation>Listo</translation>
        </message>
        <message>
            <source>Running</source>
            <translation>En marcha</translation>
        </message>
        <message>
            <source>Holding…</source>
            <translation>Pausando…</translation>
        </message>
        <message>
            <source>On hold</source>
            <translation>En pausa</translation>
        </message>
        <message>
            <source>Paused by a problem</source>
            <translation>En pausa por un problema</translation>
        </message>
        <message>
            <source>Stopping…</source>
            <translation>Deteniendo…</translation>
        </message>
        <message>
            <source>Stopped</source>
            <translation>Detenido</translation>
        </message>
        <message>
            <source>Finished</source>
            <translation>Terminado</translation>
        </message>
        <message>
            <source>%1 h %2 min</source>
            <translation>%1 h %2 min</translation>
        </message>
        <message>
            <source>%1 min %2 s</source>
            <translation>%1 min %2 s</translation>
        </message>
        <message>
            <source>%1 s</source>
            <translation>%1 s</translation>
        </message>
        <message>
            <source>Start</source>
            <translation>Iniciar</translation>
        </message>
        <message>
            <source>Write the planned job as G-code and stream it to the machine</source>
            <translation>Escribir el trabajo planificado como código G y enviarlo a la máquina</translation>
        </message>
        <message>
            <source>Hold</source>
            <translation>Pausa</translation>
        </message>
        <message>
            <source>Feed hold: the machine decelerates and waits</source>
            <translation>Pausa de avance: la máquina frena y espera</translation>
        </message>
        <message>
            <source>Continue</source>
            <translation>Continuar</translation>
        </message>
        <message>
            <source>Continue after a hold</source>
            <translation>Continuar tras una pausa</translation>
        </message>
        <message>
            <source>Stop</source>
            <translation>Detener</translation>
        </message>
        <message>
            <source>Stop the job: hold, reset and unlock; the progress is kept for a resume</source>
            <translation>Detener el trabajo: pausa, reinicio y desbloqueo; el progreso se conserva para reanudarlo</translation>
        </message>
        <message>
            <source>Resume</source>
            <translation>Reanudar</translation>
        </message>
        <message>
            <source>Continue the interrupted job from its last completed pen-down point, with a safe pen-up approach</source>
            <translation>Continuar el trabajo interrumpido desde su último punto dibujado, con una aproximación segura con la pluma subida</translation>
        </message>
        <message>
            <source>No job sent yet</source>
            <translation>Aún no se ha enviado ningún trabajo</translation>
        </message>
        <message>
            <source>%1 left</source>
            <translation>quedan %1</translation>
        </message>
        <message>
            <source>Long job</source>
            <translation>Trabajo largo</translation>
        </message>
        <message>
            <source>Start from the beginning?</source>
            <translation>¿Empezar desde el principio?</translation>
        </message>
        <message>
            <source>%1

Start draws "%2" from the beginning and discards this saved progress. Resume continues the interrupted run instead.</source>
            <translation>%1

Iniciar dibuja "%2" desde el principio y descarta este progreso guardado. Reanudar, en cambio, continúa la ejecución interrumpida.</translation>
        </message>
        <message>
            <source>Discard and start over</source>
            <translation>Descartar y empezar de nuevo</translation>
        </message>
        <message>
            <source>Cancel</source>
            <translation>Cancelar</translation>
        </message>
        <message>
            <source>Reading the board's settings to compare them with the profile: press Start again in a moment.</source>
            <translation>Leyendo los ajustes de la placa para compararlos con el perfil: pulse Iniciar de nuevo en un momento.</translation>
        </message>
        <message>
            <source>The board's settings differ</source>
            <translation>Los ajustes de la placa difieren</translation>
        </message>
        <message>
            <source>Write the profile's settings...</source>
            <translation>Escribir los ajustes del perfil...</translation>
        </message>
        <message>
            <source>Start anyway</source>
            <translation>Iniciar de todos modos</translation>
        </message>
        <message>
            <source>%1 % (%2)</source>
            <translation>%1 % (%2)</translation>
        </message>
        <message>
            <source>%1 left (on hold)</source>
            <translation>quedan %1 (en pausa)</translation>
        </message>
        <message>
            <source>Machine time left by the plan, planned again at the feed and rapid override the machine reports</source>
            <translation>Tiempo de máquina restante según el plan, replanificado con los ajustes de avance y de rápidos que informa la máquina</translation>
        </message>
    </context>
    <context>
        <name>fivebar::session::SettingsAdvice</name>
        <message>
            <source>soft limits are on, but this machine has no homing switches: the board measures its travel from where it was switched on, not from the reference pose, and stops the job with ALARM:2 when a move leaves that range.</source>
            <translation>los límites por software están activados, pero esta máquina no tiene finales de carrera para homing: la placa mide su recorrido desde donde se encendió, no desde la pose de referencia, y detiene el trabajo con ALARM:2 cuando un movimiento sale de ese rango.</translation>
        </message>
        <message>
            <source>soft limits are off although the profile expects them.</source>
            <translation>los límites por software están desactivados aunque el perfil los espera.</translation>
        </message>
        <message>
            <source>hard limits are on: without limit switches wired, noise on the pins stops the machine with ALARM:1.</source>
            <translation>los límites por hardware están activados: sin finales de carrera conectados, el ruido en los pines detiene la máquina con ALARM:1.</translation>
        </message>
        <message>
            <source>hard limits are off although the profile expects them.</source>
            <translation>los límites por hardware están desactivados aunque el perfil los espera.</translation>
        </message>
        <message>
            <source>the homing cycle is on: the board starts locked and wants $H, which needs homing switches.</source>
            <translation>el ciclo de homing está activado: la placa arranca bloqueada y pide $H, que necesita finales de carrera.</translation>
        </message>
        <message>
            <source>the homing cycle is off although the profile has switches.</source>
            <translation>el ciclo de homing está desactivado aunque el perfil tiene finales de carrera.</translation>
        </message>
        <message>
            <source>steps per degree differ: every motor angle would be wrong by the ratio, so the arms would leave the checked, safe poses.</source>
            <translation>los pasos por grado difieren: cada ángulo de motor sería erróneo en esa proporción, así que los brazos saldrían de las poses comprobadas y seguras.</translation>
        </message>
        <message>
            <source>the board's maximum rate is lower: the job runs slower than planned and the time estimate is off.</source>
            <translation>la velocidad máxima de la placa es menor: el trabajo va más lento de lo planificado y la estimación de tiempo falla.</translation>
        </message>
        <message>
            <source>the board's maximum rate is higher than the profile allows: the motors may lose steps.</source>
            <translation>la velocidad máxima de la placa es mayor de lo que permite el perfil: los motores pueden perder pasos.</translation>
        </message>
        <message>
            <source>the board accelerates more gently: the job takes longer than planned.</source>
            <translation>la placa acelera más suavemente: el trabajo tarda más de lo planificado.</translation>
        </message>
        <message>
            <source>the board accelerates harder than the profile allows: the motors may lose steps.</source>
            <translation>la placa acelera más fuerte de lo que permite el perfil: los motores pueden perder pasos.</translation>
        </message>
        <message>
            <source>the motor's travel for soft limits differs: with soft limits on, a move beyond it stops the job with ALARM:2.</source>
            <translation>el recorrido del motor para los límites por software difiere: con ellos activados, un movimiento que lo supere detiene el trabajo con ALARM:2.</translation>
        </message>
        <message>
            <source>the spindle (pen servo / laser) range differs: the pen may not lift or lower as planned.</source>
            <translation>el rango del husillo (servo de pluma / láser) difiere: puede que la pluma no suba o baje como está previsto.</translation>
        </message>
        <message>
            <source>the junction deviation differs: corners run at other speeds than planned.</source>
            <translation>la desviación de unión (junction deviation) difiere: las esquinas van a velocidades distintas de las planificadas.</translation>
        </message>
        <message>
            <source>differs from what the profile expects.</source>
            <translation>difiere de lo que espera el perfil.</translation>
        </message>
        <message>
            <source>not reported</source>
            <translation>no informado</translation>
        </message>
        <message>
            <source>$%1 is %2 on the board, the profile wants %3: %4</source>
            <translation>$%1 vale %2 en la placa, el perfil quiere %3: %4</translation>
        </message>
        <message numerus="yes">
            <source>The board's settings differ from the profile in %n place(s): %1.</source>
            <translation>
                <numerusform>Los ajustes de la placa difieren del perfil en %n punto: %1.</numerusform>
                <numerusform>Los ajustes de la placa difieren del perfil en %n puntos: %1.</numerusform>
            </translation>
        </message>
        <message>
            <source>A job would stop or move wrongly with them.</source>
            <translation>Con ellos, un trabajo se detendría o se movería mal.</translation>
        </message>
        <message>
            <source>The board's GRBL settings differ from the machine profile, and the job would not run as planned:</source>
            <translation>Los ajustes GRBL de la placa difieren del perfil de la máquina y el trabajo no se ejecutaría como está planificado:</translation>
        </message>
        <message>
            <source>The board's GRBL settings differ from the machine profile:</source>
            <translation>Los ajustes GRBL de la placa difieren del perfil de la máquina:</translation>
        </message>
        <message>
            <source>Write the profile's settings to the board (its current ones are saved to a backup file first), or start anyway.</source>
            <translation>Escriba los ajustes del perfil en la placa (los actuales se guardan antes en un archivo de copia de seguridad) o inicie de todos modos.</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::SimulationPanel</name>
        <message>
            <source>Step back one move</source>
            <translation>Retroceder un movimiento</translation>
        </message>
        <message>
            <source>Play / pause the simulation</source>
            <translation>Reproducir / pausar la simulación</translation>
        </message>
        <message>
            <source>Step forward one move</source>
            <translation>Avanzar un movimiento</translation>
        </message>
        <message>
            <source>Simulation speed</source>
            <translation>Velocidad de simulación</translation>
        </message>
        <message>
            <source>x%1</source>
            <translation>x%1</translation>
        </message>
        <message>
            <source>No planned job to simulate.</source>
            <translation>No hay ningún trabajo planificado que simular.</translation>
        </message>
        <message>
            <source>%1 of %2</source>
            <translation>%1 de %2</translation>
        </message>
        <message>
            <source>&lt;table&gt;&lt;tr&gt;&lt;td&gt;Motor angles:&lt;/td&gt;&lt;td&gt;%1 deg, %2 deg&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Pen:&lt;/td&gt;&lt;td&gt;x %3 mm, y %4 mm (%5)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Transmission angle:&lt;/td&gt;&lt;td&gt;%6 deg at the pen&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;/td&gt;&lt;td&gt;%7 / %8 deg at the elbows&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Type II margin:&lt;/td&gt;&lt;td&gt;&lt;b&gt;%9 deg&lt;/b&gt;&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</source>
            <translation>&lt;table&gt;&lt;tr&gt;&lt;td&gt;Ángulos de motor:&lt;/td&gt;&lt;td&gt;%1°, %2°&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Pluma:&lt;/td&gt;&lt;td&gt;x %3 mm, y %4 mm (%5)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Áng. de transmisión:&lt;/td&gt;&lt;td&gt;%6° en la pluma&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;/td&gt;&lt;td&gt;%7° / %8° en los codos&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Margen tipo II:&lt;/td&gt;&lt;td&gt;&lt;b&gt;%9°&lt;/b&gt;&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</translation>
        </message>
        <message>
            <source>down</source>
            <translation>bajada</translation>
        </message>
        <message>
            <source>up</source>
            <translation>subida</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::SpeedLegend</name>
        <message>
            <source>0 mm/s</source>
            <translation>0 mm/s</translation>
        </message>
        <message>
            <source>%1 mm/s</source>
            <translation>%1 mm/s</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::StudioDocument</name>
        <message>
            <source>Show layer</source>
            <translation>Mostrar capa</translation>
        </message>
        <message>
            <source>Hide layer</source>
            <translation>Ocultar capa</translation>
        </message>
        <message>
            <source>Reorder layers</source>
            <translation>Reordenar capas</translation>
        </message>
        <message>
            <source>Change layer tool settings</source>
            <translation>Cambiar los ajustes de herramienta de la capa</translation>
        </message>
        <message>
            <source>Change layer fill</source>
            <translation>Cambiar relleno de capa</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::AccuracyPage</name>
        <message>
            <source>Measure the accuracy lines</source>
            <translation>Medir las líneas de precisión</translation>
        </message>
        <message>
            <source>Hoang's accuracy pattern is ten lines, each meant to be 40 mm long and straight, 10 mm apart. Lay a steel ruler along each line. &lt;b&gt;Length&lt;/b&gt;: from end to end, in the middle of the pen's stroke. &lt;b&gt;Straightness&lt;/b&gt;: the widest gap between the line and the ruler's edge when the ruler touches both ends (0 for a straight line). Type the lines drawn &lt;b&gt;before&lt;/b&gt; calibration in the first two columns and those of the verification sheet (drawn &lt;b&gt;after&lt;/b&gt;) in the last two; the figures below compare them.</source>
            <translation>El patrón de precisión de Hoang son diez líneas, cada una pensada para medir 40 mm y ser recta, a 10 mm entre sí. Apoye una regla de acero a lo largo de cada línea. &lt;b&gt;Longitud&lt;/b&gt;: de extremo a extremo, en el centro del trazo. &lt;b&gt;Rectitud&lt;/b&gt;: la mayor separación entre la línea y el borde de la regla cuando la regla toca ambos extremos (0 para una línea recta). Escriba las líneas dibujadas &lt;b&gt;antes&lt;/b&gt; de calibrar en las dos primeras columnas y las de la hoja de verificación (dibujadas &lt;b&gt;después&lt;/b&gt;) en las dos últimas; las cifras de abajo las comparan.</translation>
        </message>
        <message>
            <source>Length before (mm)</source>
            <translation>Longitud antes (mm)</translation>
        </message>
        <message>
            <source>Straightness before (mm)</source>
            <translation>Rectitud antes (mm)</translation>
        </message>
        <message>
            <source>Length after (mm)</source>
            <translation>Longitud después (mm)</translation>
        </message>
        <message>
            <source>Straightness after (mm)</source>
            <translation>Rectitud después (mm)</translation>
        </message>
        <message>
            <source>Line %1</source>
            <translation>Línea %1</translation>
        </message>
        <message>
            <source>Simulation: measure the simulated lines</source>
            <translation>Simulación: medir las líneas simuladas</translation>
        </message>
        <message>
            <source>Fills the table with the lines as the simulated imperfect machine draws them: before with the profile the wizard started from, after with the calibrated profile.</source>
            <translation>Rellena la tabla con las líneas tal como las dibuja la máquina simulada imperfecta: antes con el perfil con el que empezó el asistente, después con el perfil calibrado.</translation>
        </message>
        <message>
            <source>Line %1, %2: '%3' is not a length in mm.</source>
            <translation>Línea %1, %2: «%3» no es una longitud en mm.</translation>
        </message>
        <message>
            <source>&lt;b&gt;%1:&lt;/b&gt; not measured yet (type a length and a straightness per line).</source>
            <translation>&lt;b&gt;%1:&lt;/b&gt; aún sin medir (escriba una longitud y una rectitud por línea).</translation>
        </message>
        <message>
            <source>&lt;b&gt;%1:&lt;/b&gt; straightness %2 mm at worst (RMS %3 mm); length off by %4 mm at worst (RMS %5 mm), over %6 lines.</source>
            <translation>&lt;b&gt;%1:&lt;/b&gt; rectitud %2 mm en el peor caso (RMS %3 mm); longitud desviada %4 mm en el peor caso (RMS %5 mm), en %6 líneas.</translation>
        </message>
        <message>
            <source>Before calibration</source>
            <translation>Antes de calibrar</translation>
        </message>
        <message>
            <source>After calibration</source>
            <translation>Después de calibrar</translation>
        </message>
        <message>
            <source>&lt;br&gt;Worst straightness plus worst length error: %1 mm &amp;rarr; &lt;b&gt;%2 mm&lt;/b&gt;.</source>
            <translation>&lt;br&gt;Peor rectitud más peor error de longitud: %1 mm &amp;rarr; &lt;b&gt;%2 mm&lt;/b&gt;.</translation>
        </message>
        <message>
            <source>&lt;br&gt;&lt;i&gt;Apply the calibration (step 5) to see the lines drawn after it.&lt;/i&gt;</source>
            <translation>&lt;br&gt;&lt;i&gt;Aplique la calibración (paso 5) para ver las líneas dibujadas después.&lt;/i&gt;</translation>
        </message>
        <message>
            <source>Import scan...</source>
            <translation>Importar escaneo...</translation>
        </message>
        <message>
            <source>A scan of the sheet with the accuracy lines (PNG or JPEG, taken straight from above): each line's length and straightness are measured in the image and fill the columns of the chosen sheet.</source>
            <translation>Un escaneo de la hoja con las líneas de precisión (PNG o JPEG, tomado de frente desde arriba): la longitud y la rectitud de cada línea se miden en la imagen y rellenan las columnas de la hoja elegida.</translation>
        </message>
        <message>
            <source>Sheet drawn before calibration</source>
            <translation>Hoja dibujada antes de la calibración</translation>
        </message>
        <message>
            <source>Sheet drawn after calibration</source>
            <translation>Hoja dibujada después de la calibración</translation>
        </message>
        <message>
            <source> dpi</source>
            <translation> dpi</translation>
        </message>
        <message>
            <source>The scanner's resolution: the scan's size in mm comes from it.</source>
            <translation>La resolución del escáner: de ella sale el tamaño del escaneo en mm.</translation>
        </message>
        <message>
            <source>Import a scan of the accuracy lines</source>
            <translation>Importar un escaneo de las líneas de precisión</translation>
        </message>
        <message>
            <source>Images (*.png *.jpg *.jpeg *.tif *.tiff *.bmp)</source>
            <translation>Imágenes (*.png *.jpg *.jpeg *.tif *.tiff *.bmp)</translation>
        </message>
        <message>
            <source>A line in the scan is too short to measure.</source>
            <translation>Una línea del escaneo es demasiado corta para medirla.</translation>
        </message>
        <message>
            <source>Found %1 lines in the scan (%2 mm pen): the %3 columns are filled.</source>
            <translation>Se encontraron %1 líneas en el escaneo (bolígrafo de %2 mm): las columnas «%3» están rellenas.</translation>
        </message>
        <message>
            <source>after</source>
            <translation>después</translation>
        </message>
        <message>
            <source>before</source>
            <translation>antes</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::ApplyPage</name>
        <message>
            <source>5. Apply the calibration to the profile</source>
            <translation>5. Aplicar la calibración al perfil</translation>
        </message>
        <message>
            <source>Applying writes the fitted link lengths into the profile and keeps the motor zeros and the backlash in its calibration section. From then on every plan, jog and check uses them. &lt;b&gt;Edit &amp;gt; Undo&lt;/b&gt; takes it back; the profile is saved with the project, and you can also save it as a profile file for other projects.</source>
            <translation>Al aplicar se escriben las longitudes de eslabón ajustadas en el perfil y se guardan los ceros de motor y la holgura en su sección de calibración. A partir de entonces, todos los planes, movimientos manuales y comprobaciones los usan. &lt;b&gt;Editar &amp;gt; Deshacer&lt;/b&gt; lo revierte; el perfil se guarda con el proyecto y también puede guardarlo como archivo de perfil para otros proyectos.</translation>
        </message>
        <message>
            <source>Apply to the profile</source>
            <translation>Aplicar al perfil</translation>
        </message>
        <message>
            <source>Save profile as...</source>
            <translation>Guardar perfil como...</translation>
        </message>
        <message>
            <source>Save the calibrated profile</source>
            <translation>Guardar el perfil calibrado</translation>
        </message>
        <message>
            <source>Machine profile (*.json)</source>
            <translation>Perfil de máquina (*.json)</translation>
        </message>
        <message>
            <source>Saved %1.</source>
            <translation>Guardado %1.</translation>
        </message>
        <message>
            <source> mm</source>
            <translation> mm</translation>
        </message>
        <message>
            <source>°</source>
            <translation>°</translation>
        </message>
        <message>
            <source>motor 1 zero</source>
            <translation>cero del motor 1</translation>
        </message>
        <message>
            <source>motor 2 zero</source>
            <translation>cero del motor 2</translation>
        </message>
        <message>
            <source>motor 1 backlash</source>
            <translation>holgura del motor 1</translation>
        </message>
        <message>
            <source>motor 2 backlash</source>
            <translation>holgura del motor 2</translation>
        </message>
        <message>
            <source>Applied. Edit &gt; Undo restores the profile as it was.</source>
            <translation>Aplicado. Editar &gt; Deshacer restaura el perfil como estaba.</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::CalibrationPreview</name>
        <message>
            <source>No pattern yet</source>
            <translation>Aún no hay patrón</translation>
        </message>
        <message>
            <source>pattern as planned</source>
            <translation>patrón según el plan</translation>
        </message>
        <message>
            <source>drawn by the pen (simulation)</source>
            <translation>dibujado por la pluma (simulación)</translation>
        </message>
        <message>
            <source>measured</source>
            <translation>medido</translation>
        </message>
        <message>
            <source>error before</source>
            <translation>error antes</translation>
        </message>
        <message>
            <source>error after</source>
            <translation>error después</translation>
        </message>
        <message>
            <source>arrows ×%1</source>
            <translation>flechas ×%1</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::CalibrationWizard</name>
        <message>
            <source>The pattern is already being drawn.</source>
            <translation>El patrón ya se está dibujando.</translation>
        </message>
        <message>
            <source>Connect a machine (or the simulated machine) in the Machine panel first, and let any running job finish.</source>
            <translation>Conecte primero una máquina (o la máquina simulada) en el panel Máquina y deje que termine cualquier trabajo en curso.</translation>
        </message>
        <message>
            <source>Calibrate the machine</source>
            <translation>Calibrar la máquina</translation>
        </message>
        <message>
            <source>&amp;Calibrate...</source>
            <translation>&amp;Calibrar...</translation>
        </message>
        <message>
            <source>Measure a drawn pattern and correct the profile's link lengths and motor zeros</source>
            <translation>Medir un patrón dibujado y corregir las longitudes de eslabón y los ceros de motor del perfil</translation>
        </message>
        <message>
            <source>Choose a pattern first.</source>
            <translation>Elija primero un patrón.</translation>
        </message>
        <message>
            <source>The pattern cannot be planned: %1</source>
            <translation>No se puede planificar el patrón: %1</translation>
        </message>
        <message>
            <source>The pattern's G-code cannot be written: %1</source>
            <translation>No se puede escribir el G-code del patrón: %1</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::DistancesBox</name>
        <message>
            <source>Only a ruler? Measure the distance between the centres of two marks and type both mark numbers and the distance. No corner or direction is needed. Measure long and short pairs across the whole sheet, each mark in several pairs: about four per mark (100 for 25 marks) calibrate as well as coordinates. Use the marks for the fit, not the backlash rows.</source>
            <translation>¿Solo una regla? Mida la distancia entre los centros de dos marcas y escriba ambos números de marca y la distancia. No hace falta esquina ni dirección. Mida pares largos y cortos por toda la hoja, cada marca en varios pares: unas cuatro por marca (100 para 25 marcas) calibran tan bien como las coordenadas. Use las marcas para el ajuste, no las filas de holgura.</translation>
        </message>
        <message>
            <source>Mark A</source>
            <translation>Marca A</translation>
        </message>
        <message>
            <source>Mark B</source>
            <translation>Marca B</translation>
        </message>
        <message>
            <source>Distance (mm)</source>
            <translation>Distancia (mm)</translation>
        </message>
        <message>
            <source>Add a row</source>
            <translation>Añadir una fila</translation>
        </message>
        <message>
            <source>Remove the row</source>
            <translation>Quitar la fila</translation>
        </message>
        <message>
            <source>Load distances CSV...</source>
            <translation>Cargar CSV de distancias...</translation>
        </message>
        <message>
            <source>A file with the columns id_a,id_b,distance_mm (as fivebar calibrate fit reads it)</source>
            <translation>Un archivo con las columnas id_a,id_b,distance_mm (como lo lee fivebar calibrate fit)</translation>
        </message>
        <message>
            <source>Simulation: measure distances on the simulated sheet</source>
            <translation>Simulación: medir distancias en la hoja simulada</translation>
        </message>
        <message>
            <source>Fills the table with distances between where the simulated imperfect machine put the marks, plus ruler noise.</source>
            <translation>Rellena la tabla con distancias entre donde la máquina simulada imperfecta puso las marcas, más el ruido de la regla.</translation>
        </message>
        <message>
            <source>noise ±</source>
            <translation>ruido ±</translation>
        </message>
        <message>
            <source> mm</source>
            <translation> mm</translation>
        </message>
        <message>
            <source>Load distances</source>
            <translation>Cargar distancias</translation>
        </message>
        <message>
            <source>CSV (*.csv)</source>
            <translation>CSV (*.csv)</translation>
        </message>
        <message>
            <source>Filled from the simulated sheet (simulation, not a measurement).</source>
            <translation>Rellenado a partir de la hoja simulada (simulación, no una medición).</translation>
        </message>
        <message>
            <source>mark A</source>
            <translation>marca A</translation>
        </message>
        <message>
            <source>mark B</source>
            <translation>marca B</translation>
        </message>
        <message>
            <source>distance</source>
            <translation>distancia</translation>
        </message>
        <message>
            <source>Row %1: %2 is empty.</source>
            <translation>Fila %1: %2 está vacía.</translation>
        </message>
        <message>
            <source>Row %1, %2: '%3' is not a number.</source>
            <translation>Fila %1, %2: «%3» no es un número.</translation>
        </message>
        <message>
            <source>Row %1: there is no mark %2 in the pattern.</source>
            <translation>Fila %1: no hay ninguna marca %2 en el patrón.</translation>
        </message>
        <message>
            <source>Row %1: mark %2 is in a backlash row; measure distances between marks for the fit.</source>
            <translation>Fila %1: la marca %2 está en una fila de holgura; mida distancias entre marcas para el ajuste.</translation>
        </message>
        <message>
            <source>Row %1: a distance from mark %2 to itself.</source>
            <translation>Fila %1: una distancia de la marca %2 a sí misma.</translation>
        </message>
        <message>
            <source>Row %1: the distance must be more than 0 mm.</source>
            <translation>Fila %1: la distancia debe ser mayor que 0 mm.</translation>
        </message>
        <message>
            <source>%1 holds mark coordinates, not distances: load it in the Coordinates tab.</source>
            <translation>%1 contiene coordenadas de marcas, no distancias: cárguelo en la pestaña Coordenadas.</translation>
        </message>
        <message>
            <source>%1:%2: the pattern's marks are numbered; '%3' is not a mark number.</source>
            <translation>%1:%2: las marcas del patrón están numeradas; «%3» no es un número de marca.</translation>
        </message>
        <message>
            <source>Loaded %1 distances from %2.</source>
            <translation>%1 distancias cargadas de %2.</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::DrawPage</name>
        <message>
            <source>2. Draw the pattern</source>
            <translation>2. Dibujar el patrón</translation>
        </message>
        <message>
            <source>Tape a sheet down so it cannot move, and draw the pattern with the pen you normally use. Draw it on the connected machine, or export its G-code and send it your way. Keep MARKS.csv: it says which motor angles drew each mark.</source>
            <translation>Fije una hoja con cinta para que no se mueva y dibuje el patrón con la pluma que usa normalmente. Dibújelo en la máquina conectada, o exporte su G-code y envíelo a su manera. Conserve MARKS.csv: indica qué ángulos de motor dibujaron cada marca.</translation>
        </message>
        <message>
            <source>Draw on the connected machine</source>
            <translation>Dibujar en la máquina conectada</translation>
        </message>
        <message>
            <source>Export G-code...</source>
            <translation>Exportar G-code...</translation>
        </message>
        <message>
            <source>Export MARKS.csv...</source>
            <translation>Exportar MARKS.csv...</translation>
        </message>
        <message>
            <source>No hardware? Simulate an imperfect machine</source>
            <translation>¿Sin hardware? Simular una máquina imperfecta</translation>
        </message>
        <message>
            <source>Simulate an imperfect machine (the sheet below is what it draws)</source>
            <translation>Simular una máquina imperfecta (la hoja de abajo es lo que dibuja)</translation>
        </message>
        <message>
            <source>The pattern is drawn. Take the sheet off and measure it.</source>
            <translation>El patrón está dibujado. Retire la hoja y mídala.</translation>
        </message>
        <message>
            <source>Drawing the pattern (%1 lines of G-code)...</source>
            <translation>Dibujando el patrón (%1 líneas de G-code)...</translation>
        </message>
        <message>
            <source>Export the pattern's G-code</source>
            <translation>Exportar el G-code del patrón</translation>
        </message>
        <message>
            <source>G-code (*.gcode *.nc)</source>
            <translation>G-code (*.gcode *.nc)</translation>
        </message>
        <message>
            <source>Wrote %1.</source>
            <translation>Escrito %1.</translation>
        </message>
        <message>
            <source>Export MARKS.csv</source>
            <translation>Exportar MARKS.csv</translation>
        </message>
        <message>
            <source>CSV (*.csv)</source>
            <translation>CSV (*.csv)</translation>
        </message>
        <message>
            <source>Streams the pattern with the same checks as the Run panel</source>
            <translation>Envía el patrón con las mismas comprobaciones que el panel Ejecutar</translation>
        </message>
        <message>
            <source>Connect a machine or the simulated machine in the Machine panel first</source>
            <translation>Conecte primero una máquina o la máquina simulada en el panel Máquina</translation>
        </message>
        <message>
            <source>The simulated machine differs from the profile by these amounts, as a real one would. The picture shows what its pen really draws (orange) beside the plan. The built-in simulated machine (Machine panel) becomes this machine at once, also when it is connected. When the wizard closes it goes back to the studio's setting (Machine &amp;gt; Simulated machine...), unless you keep it.</source>
            <translation>La máquina simulada difiere del perfil en estos valores, como lo haría una real. La imagen muestra lo que su bolígrafo dibuja de verdad (naranja) junto al plan. La máquina simulada integrada (panel Máquina) pasa a ser esta máquina al momento, también conectada. Al cerrar el asistente vuelve el ajuste del estudio (Máquina &amp;gt; Máquina simulada...), salvo que la conserve.</translation>
        </message>
        <message>
            <source>Keep this machine as the studio's simulated machine after the wizard</source>
            <translation>Conservar esta máquina como máquina simulada del estudio tras el asistente</translation>
        </message>
        <message>
            <source>Saved in Machine &gt; Simulated machine...; the status bar shows it while it is imperfect</source>
            <translation>Guardada en Máquina &gt; Máquina simulada...; la barra de estado la muestra mientras sea imperfecta</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::FitPage</name>
        <message>
            <source>4. Fit the machine to the marks</source>
            <translation>4. Ajustar la máquina a las marcas</translation>
        </message>
        <message>
            <source>The fit looks for the link lengths and motor zeros with which the machine would have put every mark where you measured it. Some marks are kept out of the fit and only used to check it afterwards ("held out"): their error is the honest one. The arrows show each mark's error, greatly enlarged: grey before, red after.</source>
            <translation>El ajuste busca las longitudes de eslabón y los ceros de motor con los que la máquina habría puesto cada marca donde usted la midió. Algunas marcas quedan fuera del ajuste y solo sirven para comprobarlo después ("reservadas"): su error es el honesto. Las flechas muestran el error de cada marca, muy ampliado: gris antes, rojo después.</translation>
        </message>
        <message>
            <source>Parameter</source>
            <translation>Parámetro</translation>
        </message>
        <message>
            <source>Profile</source>
            <translation>Perfil</translation>
        </message>
        <message>
            <source>Fitted ± std. dev.</source>
            <translation>Ajustado ± desv. est.</translation>
        </message>
        <message>
            <source>&lt;span style='color:#b00000'&gt;&lt;b&gt;The fit failed:&lt;/b&gt; %1&lt;/span&gt;&lt;br&gt;Go back, check the table, or measure more marks.</source>
            <translation>&lt;span style='color:#b00000'&gt;&lt;b&gt;El ajuste falló:&lt;/b&gt; %1&lt;/span&gt;&lt;br&gt;Vuelva atrás, revise la tabla o mida más marcas.</translation>
        </message>
        <message>
            <source>Backlash from %1 + %2 rows: motor 1 %3°, motor 2 %4°.</source>
            <translation>Holgura a partir de %1 + %2 filas: motor 1 %3°, motor 2 %4°.</translation>
        </message>
        <message>
            <source>Backlash not measured: %1</source>
            <translation>Holgura no medida: %1</translation>
        </message>
        <message>
            <source>No mark looks mis-measured.</source>
            <translation>Ninguna marca parece mal medida.</translation>
        </message>
        <message>
            <source>&lt;span style='color:#b00000'&gt;Left out as mis-measured: mark %1. Check it on the sheet.&lt;/span&gt;</source>
            <translation>&lt;span style='color:#b00000'&gt;Excluida por mal medida: marca %1. Revísela en la hoja.&lt;/span&gt;</translation>
        </message>
        <message>
            <source>°</source>
            <translation>°</translation>
        </message>
        <message>
            <source> mm</source>
            <translation> mm</translation>
        </message>
        <message>
            <source>%1 ± %2%3</source>
            <translation>%1 ± %2%3</translation>
        </message>
        <message>
            <source>Backlash is not measured from distances (it needs the positions of the backlash rows' marks); the profile's backlash is kept.</source>
            <translation>La holgura no se mide a partir de distancias (hacen falta las posiciones de las marcas de las filas de holgura); se conserva la holgura del perfil.</translation>
        </message>
        <message>
            <source>&lt;span style='color:#b00000'&gt;Left out as mis-measured: distance %1 (marks A-B). Measure it again.&lt;/span&gt;</source>
            <translation>&lt;span style='color:#b00000'&gt;Descartada por mal medida: distancia %1 (marcas A-B). Mídala de nuevo.&lt;/span&gt;</translation>
        </message>
        <message>
            <source>&lt;b&gt;Distance error before: %1 mm RMS&lt;/b&gt; (largest %2 mm) &amp;rarr; &lt;b&gt;after: %3 mm RMS&lt;/b&gt; (largest %4 mm) over %5 distances.</source>
            <translation>&lt;b&gt;Error de distancia antes: %1 mm RMS&lt;/b&gt; (mayor %2 mm) &amp;rarr; &lt;b&gt;después: %3 mm RMS&lt;/b&gt; (mayor %4 mm) en %5 distancias.</translation>
        </message>
        <message>
            <source>&lt;b&gt;Error before: %1 mm RMS&lt;/b&gt; (largest %2 mm) &amp;rarr; &lt;b&gt;after: %3 mm RMS&lt;/b&gt; (largest %4 mm) over %5 marks.</source>
            <translation>&lt;b&gt;Error antes: %1 mm RMS&lt;/b&gt; (mayor %2 mm) &amp;rarr; &lt;b&gt;después: %3 mm RMS&lt;/b&gt; (mayor %4 mm) en %5 marcas.</translation>
        </message>
        <message>
            <source>&lt;br&gt;Held-out measurements (%1): %2 mm before &amp;rarr; %3 mm after.&lt;br&gt;%4&lt;br&gt;%5&lt;br&gt;&lt;small&gt;Condition number %6 (below 10000 is fine).&lt;/small&gt;</source>
            <translation>&lt;br&gt;Mediciones reservadas (%1): %2 mm antes &amp;rarr; %3 mm después.&lt;br&gt;%4&lt;br&gt;%5&lt;br&gt;&lt;small&gt;Número de condición %6 (por debajo de 10000 está bien).&lt;/small&gt;</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::MeasurePage</name>
        <message>
            <source>3. Measure the marks</source>
            <translation>3. Medir las marcas</translation>
        </message>
        <message>
            <source>Mark</source>
            <translation>Marca</translation>
        </message>
        <message>
            <source>Kind</source>
            <translation>Tipo</translation>
        </message>
        <message>
            <source>x (mm)</source>
            <translation>x (mm)</translation>
        </message>
        <message>
            <source>y (mm)</source>
            <translation>y (mm)</translation>
        </message>
        <message>
            <source>Simulation: measure the simulated sheet</source>
            <translation>Simulación: medir la hoja simulada</translation>
        </message>
        <message>
            <source>Fills the table with where the simulated imperfect machine put each mark, plus ruler noise. For trying the wizard without hardware.</source>
            <translation>Rellena la tabla con dónde puso cada marca la máquina imperfecta simulada, más ruido de regla. Para probar el asistente sin hardware.</translation>
        </message>
        <message>
            <source>noise ±</source>
            <translation>ruido ±</translation>
        </message>
        <message>
            <source> mm</source>
            <translation> mm</translation>
        </message>
        <message>
            <source>Import a scan...</source>
            <translation>Importar un escaneo...</translation>
        </message>
        <message>
            <source>A scan or photo taken straight from above (PNG or JPEG): the marks are found and numbered by themselves.</source>
            <translation>Un escaneo o foto tomada justo desde arriba (PNG o JPEG): las marcas se encuentran y numeran automáticamente.</translation>
        </message>
        <message>
            <source> dpi</source>
            <translation> dpi</translation>
        </message>
        <message>
            <source>The scanner's resolution: the scan's size in mm comes from it.</source>
            <translation>La resolución del escáner: de ella sale el tamaño del escaneo en mm.</translation>
        </message>
        <message>
            <source>Load MEASURED.csv...</source>
            <translation>Cargar MEASURED.csv...</translation>
        </message>
        <message>
            <source>Save MEASURED.csv...</source>
            <translation>Guardar MEASURED.csv...</translation>
        </message>
        <message>
            <source>Import a scan of the sheet</source>
            <translation>Importar un escaneo de la hoja</translation>
        </message>
        <message>
            <source>Images (*.png *.jpg *.jpeg *.tif *.tiff *.bmp)</source>
            <translation>Imágenes (*.png *.jpg *.jpeg *.tif *.tiff *.bmp)</translation>
        </message>
        <message>
            <source>Load MEASURED.csv</source>
            <translation>Cargar MEASURED.csv</translation>
        </message>
        <message>
            <source>CSV (*.csv)</source>
            <translation>CSV (*.csv)</translation>
        </message>
        <message>
            <source>Save MEASURED.csv</source>
            <translation>Guardar MEASURED.csv</translation>
        </message>
        <message>
            <source>fit</source>
            <translation>ajuste</translation>
        </message>
        <message>
            <source>backlash %1</source>
            <translation>holgura %1</translation>
        </message>
        <message>
            <source>Filled from the simulated sheet (simulation, not a measurement).</source>
            <translation>Rellenado a partir de la hoja simulada (simulación, no una medición).</translation>
        </message>
        <message>
            <source>Mark %1: %2 is empty. Type both x and y, or leave both empty.</source>
            <translation>Marca %1: %2 está vacío. Escriba x e y, o deje ambos vacíos.</translation>
        </message>
        <message>
            <source>Mark %1, %2: '%3' is not a number.</source>
            <translation>Marca %1, %2: '%3' no es un número.</translation>
        </message>
        <message>
            <source>Only %1 marks for the fit are measured; measure at least %2 (the fit finds 5 lengths, 2 motor zeros and how the sheet lay).</source>
            <translation>Solo hay %1 marcas medidas para el ajuste; mida al menos %2 (el ajuste busca 5 longitudes, 2 ceros de motor y cómo estaba la hoja).</translation>
        </message>
        <message>
            <source>Cannot read %1: %2</source>
            <translation>No se puede leer %1: %2</translation>
        </message>
        <message>
            <source>Found %1 of %2 marks in the scan (sheet turned %3°%4).%5</source>
            <translation>Se encontraron %1 de %2 marcas en el escaneo (hoja girada %3°%4).%5</translation>
        </message>
        <message>
            <source>, mirrored</source>
            <translation>, reflejada</translation>
        </message>
        <message>
            <source> Not found: %1; type them in by hand.</source>
            <translation> No encontradas: %1; introdúzcalas a mano.</translation>
        </message>
        <message>
            <source>Cannot write %1: %2</source>
            <translation>No se puede escribir %1: %2</translation>
        </message>
        <message>
            <source>Measure the centre of each numbered dot with a ruler and type its x and y in millimetres. Any corner of the sheet can be the origin, and y may point up or down: the fit finds how the sheet lay. The mark you are typing is circled on the picture. Leave a row empty if a mark cannot be read; a mis-measured mark is found and named by the fit. With a scanner, import a scan instead: the marks are found and numbered for you. With a ruler alone, measure distances between marks in the second tab.</source>
            <translation>Mida el centro de cada punto numerado con una regla y escriba su x y su y en milímetros. Cualquier esquina de la hoja puede ser el origen, y la y puede apuntar hacia arriba o hacia abajo: el ajuste encuentra cómo estaba la hoja. La marca que está escribiendo aparece rodeada en la imagen. Deje una fila vacía si una marca no se puede leer; el ajuste encuentra y nombra una marca mal medida. Con un escáner, importe un escaneo: las marcas se encuentran y numeran solas. Con una regla sola, mida distancias entre marcas en la segunda pestaña.</translation>
        </message>
        <message>
            <source>Coordinates (x, y)</source>
            <translation>Coordenadas (x, y)</translation>
        </message>
        <message>
            <source>Distances between marks</source>
            <translation>Distancias entre marcas</translation>
        </message>
        <message>
            <source>Only %1 distances are measured; measure at least %2, about four for each mark (the fit finds 5 lengths and 2 motor zeros).</source>
            <translation>Solo hay %1 distancias medidas; mida al menos %2, unas cuatro por marca (el ajuste busca 5 longitudes y 2 ceros de motor).</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::PatternPage</name>
        <message>
            <source>1. Choose the pattern</source>
            <translation>1. Elegir el patrón</translation>
        </message>
        <message>
            <source>Calibration marks</source>
            <translation>Marcas de calibración</translation>
        </message>
        <message>
            <source>Accuracy pattern only (10 lines)</source>
            <translation>Solo patrón de precisión (10 líneas)</translation>
        </message>
        <message>
            <source> marks</source>
            <translation> marcas</translation>
        </message>
        <message>
            <source>More marks: a more certain fit, more to measure. 25 is a good start.</source>
            <translation>Más marcas: un ajuste más fiable, más que medir. 25 es un buen comienzo.</translation>
        </message>
        <message>
            <source>Marks for the fit:</source>
            <translation>Marcas para el ajuste:</translation>
        </message>
        <message>
            <source>&lt;span style='color:#b00000'&gt;%1&lt;/span&gt;</source>
            <translation>&lt;span style='color:#b00000'&gt;%1&lt;/span&gt;</translation>
        </message>
        <message>
            <source>For &lt;b&gt;%1&lt;/b&gt;: %2 marks for the fit and %3 marks in backlash rows%4.</source>
            <translation>Para &lt;b&gt;%1&lt;/b&gt;: %2 marcas para el ajuste y %3 marcas en filas de holgura%4.</translation>
        </message>
        <message>
            <source>, with the accuracy lines in the middle</source>
            <translation>, con las líneas de precisión en el centro</translation>
        </message>
        <message>
            <source>For &lt;b&gt;%1&lt;/b&gt;: ten lines of 40 mm in the middle of the working area.</source>
            <translation>Para &lt;b&gt;%1&lt;/b&gt;: diez líneas de 40 mm en el centro del área de trabajo.</translation>
        </message>
        <message>
            <source>No machine is built exactly as drawn: a link cut half a millimetre long or a motor zero set by eye bends every drawing. The studio draws a &lt;b&gt;pattern&lt;/b&gt; of numbered marks, you measure where they really landed, and a fit finds the machine's true link lengths and motor zeros.&lt;br&gt;&lt;br&gt;&lt;b&gt;Calibration marks&lt;/b&gt;: numbered dots in rings spread over the whole working area, plus rows that show the slack (backlash) of each motor. Use these to calibrate.&lt;br&gt;&lt;b&gt;Accuracy pattern&lt;/b&gt; (Hoang): ten parallel lines, 40 mm long and 10 mm apart, to judge straightness and length before and after: you measure each line's length and straightness with a ruler in the wizard's last step.</source>
            <translation>Ninguna máquina se construye exactamente como se dibujó: un eslabón cortado medio milímetro largo o un cero de motor ajustado a ojo deforma cada dibujo. El estudio dibuja un &lt;b&gt;patrón&lt;/b&gt; de marcas numeradas, usted mide dónde cayeron de verdad y un ajuste encuentra las longitudes reales de los eslabones y los ceros de los motores.&lt;br&gt;&lt;br&gt;&lt;b&gt;Marcas de calibración&lt;/b&gt;: puntos numerados en anillos repartidos por toda el área de trabajo, más filas que muestran la holgura de cada motor. Úselas para calibrar.&lt;br&gt;&lt;b&gt;Patrón de precisión&lt;/b&gt; (Hoang): diez líneas paralelas, de 40 mm de largo y a 10 mm entre sí, para juzgar la rectitud y la longitud antes y después: usted mide la longitud y la rectitud de cada línea con una regla en el último paso del asistente.</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::SheetLayer</name>
        <message>
            <source>Calibration pattern (plan)</source>
            <translation>Patrón de calibración (plan)</translation>
        </message>
        <message>
            <source>Drawn by the pen (simulated imperfect machine)</source>
            <translation>Dibujado por la pluma (máquina imperfecta simulada)</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::SimTraceLayer</name>
        <message>
            <source>Drawn by the simulated pen (imperfect machine)</source>
            <translation>Dibujado por el bolígrafo simulado (máquina imperfecta)</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::SimulatedMachineDialog</name>
        <message>
            <source>Simulated machine</source>
            <translation>Máquina simulada</translation>
        </message>
        <message>
            <source>The built-in simulated machine can be built &lt;b&gt;imperfectly&lt;/b&gt;, as a real one is: its links a little longer or shorter than the profile says, its motor zeros off, play in its drives. It then draws what such a machine really draws (shown on the canvas beside the plan), so you can try calibration (Machine &amp;gt; Calibrate...) without hardware.&lt;br&gt;&lt;br&gt;The amounts apply at once, also to a simulated machine that is connected, and are kept until you change them here. The status bar says so while the machine is imperfect.</source>
            <translation>La máquina simulada integrada puede construirse &lt;b&gt;imperfecta&lt;/b&gt;, como una real: sus eslabones algo más largos o cortos de lo que dice el perfil, sus ceros de motor desviados, holgura en sus transmisiones. Entonces dibuja lo que tal máquina dibuja de verdad (en el lienzo junto al plan), para probar la calibración (Máquina &amp;gt; Calibrar...) sin hardware.&lt;br&gt;&lt;br&gt;Los valores se aplican al momento, también a una máquina simulada conectada, y se mantienen hasta que los cambie aquí. La barra de estado lo indica mientras la máquina sea imperfecta.</translation>
        </message>
        <message>
            <source>Perfect machine</source>
            <translation>Máquina perfecta</translation>
        </message>
        <message>
            <source>All amounts zero: the simulated machine is exactly the profile</source>
            <translation>Todos los valores a cero: la máquina simulada es exactamente el perfil</translation>
        </message>
        <message>
            <source>Example</source>
            <translation>Ejemplo</translation>
        </message>
        <message>
            <source>A typical home-built machine: links off by up to 0.5 mm, zeros by about 1°, some play</source>
            <translation>Una máquina casera típica: eslabones desviados hasta 0,5 mm, ceros en torno a 1°, algo de holgura</translation>
        </message>
        <message>
            <source>Simulated &amp;machine...</source>
            <translation>&amp;Máquina simulada...</translation>
        </message>
        <message>
            <source>Build the simulated machine imperfectly, to try calibration without hardware</source>
            <translation>Construir la máquina simulada imperfecta, para probar la calibración sin hardware</translation>
        </message>
        <message>
            <source>OK</source>
            <translation>Aceptar</translation>
        </message>
        <message>
            <source>Cancel</source>
            <translation>Cancelar</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::SimulatedTruth</name>
        <message>
            <source>%1 %2 mm</source>
            <translation>%1 %2 mm</translation>
        </message>
        <message>
            <source>motor %1 zero %2°</source>
            <translation>cero del motor %1 %2°</translation>
        </message>
        <message>
            <source>motor %1 backlash %2°</source>
            <translation>holgura del motor %1 %2°</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::SimulatedTruthBadge</name>
        <message>
            <source>Simulated machine: imperfect</source>
            <translation>Máquina simulada: imperfecta</translation>
        </message>
        <message>
            <source>The built-in simulated machine differs from the profile: %1. Click to change it (Machine &gt; Simulated machine...).</source>
            <translation>La máquina simulada integrada difiere del perfil: %1. Haga clic para cambiarla (Máquina &gt; Máquina simulada...).</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::TrueMachineForm</name>
        <message>
            <source>How much longer the real part is than the profile says (negative: shorter).</source>
            <translation>Cuánto más larga es la pieza real de lo que dice el perfil (negativo: más corta).</translation>
        </message>
        <message>
            <source>a1 longer by</source>
            <translation>a1 más largo en</translation>
        </message>
        <message>
            <source> mm</source>
            <translation> mm</translation>
        </message>
        <message>
            <source>b1 longer by</source>
            <translation>b1 más largo en</translation>
        </message>
        <message>
            <source>a2 longer by</source>
            <translation>a2 más largo en</translation>
        </message>
        <message>
            <source>b2 longer by</source>
            <translation>b2 más largo en</translation>
        </message>
        <message>
            <source>motors farther apart by</source>
            <translation>motores más separados en</translation>
        </message>
        <message>
            <source>How much farther apart the real motor axes are.</source>
            <translation>Cuánto más separados están los ejes reales de los motores.</translation>
        </message>
        <message>
            <source>motor 1 zero off by</source>
            <translation>cero del motor 1 desviado en</translation>
        </message>
        <message>
            <source> °</source>
            <translation> °</translation>
        </message>
        <message>
            <source>The real arm angle is the commanded one plus this.</source>
            <translation>El ángulo real del brazo es el ordenado más este valor.</translation>
        </message>
        <message>
            <source>motor 2 zero off by</source>
            <translation>cero del motor 2 desviado en</translation>
        </message>
        <message>
            <source>motor 1 backlash</source>
            <translation>holgura del motor 1</translation>
        </message>
        <message>
            <source>Play in the drive: the arm lags this much when the motor reverses.</source>
            <translation>Holgura en la transmisión: el brazo se retrasa esto cuando el motor invierte el sentido.</translation>
        </message>
        <message>
            <source>motor 2 backlash</source>
            <translation>holgura del motor 2</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::VerifyPage</name>
        <message>
            <source>6. Draw the verification pattern</source>
            <translation>6. Dibujar el patrón de verificación</translation>
        </message>
        <message>
            <source>Draw on the connected machine</source>
            <translation>Dibujar en la máquina conectada</translation>
        </message>
        <message>
            <source>Export G-code...</source>
            <translation>Exportar G-code...</translation>
        </message>
        <message>
            <source>The verification pattern is drawn.</source>
            <translation>El patrón de verificación está dibujado.</translation>
        </message>
        <message>
            <source>Drawing the verification pattern...</source>
            <translation>Dibujando el patrón de verificación...</translation>
        </message>
        <message>
            <source>Export the verification G-code</source>
            <translation>Exportar el G-code de verificación</translation>
        </message>
        <message>
            <source>G-code (*.gcode *.nc)</source>
            <translation>G-code (*.gcode *.nc)</translation>
        </message>
        <message>
            <source>Wrote %1.</source>
            <translation>Escrito %1.</translation>
        </message>
        <message>
            <source>Cannot write %1.</source>
            <translation>No se puede escribir %1.</translation>
        </message>
        <message>
            <source>&lt;b&gt;Simulation:&lt;/b&gt; the imperfect machine puts the marks %1 mm RMS (largest %2 mm) from where they are meant with the old profile, and &lt;b&gt;%3 mm RMS (largest %4 mm)&lt;/b&gt; with the profile now in use%5.</source>
            <translation>&lt;b&gt;Simulación:&lt;/b&gt; la máquina imperfecta pone las marcas a %1 mm RMS (máx. %2 mm) de donde deberían con el perfil antiguo, y a &lt;b&gt;%3 mm RMS (máx. %4 mm)&lt;/b&gt; con el perfil en uso ahora%5.</translation>
        </message>
        <message>
            <source> (the calibration is not applied)</source>
            <translation> (la calibración no está aplicada)</translation>
        </message>
        <message>
            <source>Draw the pattern once more, now planned with the calibrated profile, on a fresh sheet. Its marks should land where they were meant, and the accuracy lines should be straight and 40 mm long: &lt;b&gt;Next&lt;/b&gt; measures the lines with a ruler for a before/after figure.</source>
            <translation>Dibuje el patrón una vez más, ahora planificado con el perfil calibrado, en una hoja nueva. Sus marcas deberían caer donde se pretendía, y las líneas de precisión deberían ser rectas y de 40 mm: &lt;b&gt;Siguiente&lt;/b&gt; mide las líneas con una regla para una cifra de antes/después.</translation>
        </message>
    </context>
    <context>
        <name>main</name>
        <message>
            <source>Plan and simulate drawings for five-bar robots.</source>
            <translation>Planifica y simula dibujos para robots de cinco barras.</translation>
        </message>
        <message>
            <source>Open the demo drawing on the default maker plotter.</source>
            <translation>Abrir el dibujo de demostración en el plóter maker predeterminado.</translation>
        </message>
        <message>
            <source>Save a picture of the window once the job is planned, then quit.</source>
            <translation>Guardar una imagen de la ventana una vez planificado el trabajo y salir.</translation>
        </message>
        <message>
            <source>With --screenshot: show the workspace legend (legend) or a map (transmission, conditioning or resolution).</source>
            <translation>Con --screenshot: mostrar la leyenda del espacio de trabajo (legend) o un mapa (transmission, conditioning o resolution).</translation>
        </message>
        <message>
            <source>With --screenshot: simulation position as a fraction of the job (0 to 1).</source>
            <translation>Con --screenshot: posición de la simulación como fracción del trabajo (0 a 1).</translation>
        </message>
        <message>
            <source>Print how long opening and planning the drawing took, stage by stage, to stderr (as fivebar plan --timings).</source>
            <translation>Mostrar en stderr cuánto tardó abrir y planificar el dibujo, etapa por etapa (como fivebar plan --timings).</translation>
        </message>
        <message>
            <source>Machine profile: a preset name or a profile JSON file (default: the last one used, else maker-plotter).</source>
            <translation>Perfil de máquina: un nombre de preajuste o un archivo de perfil JSON (predeterminado: el último usado, si no, maker-plotter).</translation>
        </message>
        <message>
            <source>Plan the drawing or project as the studio does, write the G-code and exit (no window).</source>
            <translation>Planificar el dibujo o proyecto como lo hace el estudio, escribir el código G y salir (sin ventana).</translation>
        </message>
        <message>
            <source>SVG drawing or project to open.</source>
            <translation>Dibujo SVG o proyecto que abrir.</translation>
        </message>
        <message>
            <source>Filled shapes: outline (default), hatch or none; with hatch: SPACING_MM and ANGLE_DEG after colons.</source>
            <translation>Formas rellenas: outline (predeterminado), hatch o none; con hatch: SPACING_MM y ANGLE_DEG tras dos puntos.</translation>
        </message>
        <message>
            <source>User interface language: de, en, es or fr (default: View &gt; Language, else the system's).</source>
            <translation>Idioma de la interfaz: de, en, es o fr (predeterminado: Ver &gt; Idioma, si no, el del sistema).</translation>
        </message>
        <message>
            <source>Connect to the board on this port at start, as the Connect button does: a serial device, a pseudo-terminal or tcp:HOST:PORT.</source>
            <translation>Conectar al inicio con la placa en este puerto, como hace el botón Conectar: un dispositivo serie, un pseudoterminal o tcp:HOST:PORT.</translation>
        </message>
        <message>
            <source>With --port: the baud rate (default: the machine profile's, usually 115200).</source>
            <translation>Con --port: la velocidad en baudios (predeterminada: la del perfil de máquina, normalmente 115200).</translation>
        </message>
    </context>
    <context>
        <name>Profile</name>
        <message>
            <source>deg</source>
            <translation>°</translation>
        </message>
        <message>
            <source>%1 must be a finite number of millimetres</source>
            <translation>%1 debe ser un número finito de milímetros</translation>
        </message>
        <message>
            <source>%1 is %2 mm; it must be zero or positive</source>
            <translation>%1 es %2 mm; debe ser cero o positivo</translation>
        </message>
        <message>
            <source>%1 is %2 mm; it must be positive</source>
            <translation>%1 es %2 mm; debe ser positivo</translation>
        </message>
        <message>
            <source>the legs can never meet: a1+b1 + a2+b2 = %1 mm is less than w = %2 mm</source>
            <translation>los brazos nunca pueden unirse: a1+b1 + a2+b2 = %1 mm es menor que w = %2 mm</translation>
        </message>
        <message>
            <source>the legs can never meet: one leg's dead zone |a-b| encloses the other leg's whole reach</source>
            <translation>los brazos nunca pueden unirse: la zona muerta |a-b| de un brazo encierra todo el alcance del otro</translation>
        </message>
        <message>
            <source>%1 limits must be finite numbers of degrees</source>
            <translation>los límites de %1 deben ser números finitos de grados</translation>
        </message>
        <message>
            <source>%1 minimum %2 deg is not below its maximum %3 deg, so no pose is allowed</source>
            <translation>el mínimo de %1 (%2°) no es menor que su máximo (%3°), así que no se permite ninguna postura</translation>
        </message>
        <message>
            <source>the joint limits exclude every pose in which the linkage closes</source>
            <translation>los límites de las articulaciones excluyen todas las posturas en las que el mecanismo se cierra</translation>
        </message>
        <message>
            <source>calibration.version %1 is not supported; this program reads version %2</source>
            <translation>calibration.version %1 no es compatible; este programa lee la versión %2</translation>
        </message>
        <message>
            <source>calibration.date must be an ISO 8601 date like 2026-12-01 or 2026-12-01T22:30:00Z, got "%1"</source>
            <translation>calibration.date debe ser una fecha ISO 8601 como 2026-12-01 o 2026-12-01T22:30:00Z, no "%1"</translation>
        </message>
        <message>
            <source>calibration.outliers[%1] must be a mark id, got an empty string</source>
            <translation>calibration.outliers[%1] debe ser un identificador de marca, no una cadena vacía</translation>
        </message>
        <message>
            <source>%1 must be a finite number</source>
            <translation>%1 debe ser un número finito</translation>
        </message>
        <message>
            <source>%1 (%2) must be below %3 (%4)</source>
            <translation>%1 (%2) debe ser menor que %3 (%4)</translation>
        </message>
        <message>
            <source>tool.zUpMm (%1) must be above tool.zDownMm (%2)</source>
            <translation>tool.zUpMm (%1) debe ser mayor que tool.zDownMm (%2)</translation>
        </message>
        <message>
            <source>%1 (%2) lies outside the joint limits [%3, %4]</source>
            <translation>%1 (%2) está fuera de los límites de las articulaciones [%3; %4]</translation>
        </message>
        <message>
            <source>name must not be empty</source>
            <translation>name no debe estar vacío</translation>
        </message>
        <message>
            <source>workingMode must be one of ++, +-, -+, --, got "%1"</source>
            <translation>workingMode debe ser ++, +-, -+ o --, no "%1"</translation>
        </message>
        <message>
            <source>assemblyMode must be + or -, got "%1"</source>
            <translation>assemblyMode debe ser + o -, no "%1"</translation>
        </message>
        <message>
            <source>tool.kind must be pen-servo, z-axis or laser, got "%1"</source>
            <translation>tool.kind debe ser pen-servo, z-axis o laser, no "%1"</translation>
        </message>
        <message>
            <source>schema must be "%1", got "%2" (is this a machine profile?)</source>
            <translation>schema debe ser "%1", no "%2" (¿es un perfil de máquina?)</translation>
        </message>
        <message>
            <source>version %1 is not supported; this program reads version %2</source>
            <translation>la versión %1 no es compatible; este programa lee la versión %2</translation>
        </message>
        <message>
            <source>%1:%2:%3: invalid JSON: %4</source>
            <translation>%1:%2:%3: JSON no válido: %4</translation>
        </message>
        <message>
            <source>the profile must be a JSON object ({...})</source>
            <translation>el perfil debe ser un objeto JSON ({...})</translation>
        </message>
        <message>
            <source>%1 must be positive, got %2</source>
            <translation>%1 debe ser positivo, no %2</translation>
        </message>
        <message>
            <source>%1 must be zero or positive, got %2</source>
            <translation>%1 debe ser cero o positivo, no %2</translation>
        </message>
        <message>
            <source>%1 must be between %2 and %3 %4, got %5</source>
            <translation>%1 debe estar entre %2 y %3 %4, no %5</translation>
        </message>
        <message>
            <source>%1 must be between %2 and %3, got %4</source>
            <translation>%1 debe estar entre %2 y %3, no %4</translation>
        </message>
        <message>
            <source>cannot open %1: %2</source>
            <translation>no se puede abrir %1: %2</translation>
        </message>
        <message>
            <source>unknown machine preset '%1' (presets: %2; or give a profile file path)</source>
            <translation>preajuste de máquina desconocido '%1' (preajustes: %2; o indique la ruta de un archivo de perfil)</translation>
        </message>
        <message>
            <source>a number</source>
            <translation>un número</translation>
        </message>
        <message>
            <source>a string</source>
            <translation>una cadena</translation>
        </message>
        <message>
            <source>a boolean</source>
            <translation>un booleano</translation>
        </message>
        <message>
            <source>an object</source>
            <translation>un objeto</translation>
        </message>
        <message>
            <source>an array</source>
            <translation>una lista</translation>
        </message>
        <message>
            <source>null</source>
            <translation>null</translation>
        </message>
        <message>
            <source>an unsupported value</source>
            <translation>un valor no admitido</translation>
        </message>
        <message>
            <source>%1 is missing (it is required)</source>
            <translation>falta %1 (es obligatorio)</translation>
        </message>
        <message>
            <source>%1 must be %2, got %3 "%4"</source>
            <translation>%1 debe ser %2, no %3 "%4"</translation>
        </message>
        <message>
            <source>%1 must be %2, got %3</source>
            <translation>%1 debe ser %2, no %3</translation>
        </message>
        <message>
            <source>an integer</source>
            <translation>un número entero</translation>
        </message>
        <message>
            <source>%1 is out of the integer range</source>
            <translation>%1 está fuera del rango de los enteros</translation>
        </message>
        <message>
            <source>true or false</source>
            <translation>true o false</translation>
        </message>
        <message>
            <source>an array of strings</source>
            <translation>una lista de cadenas</translation>
        </message>
        <message>
            <source>%1 must be a string, got %2</source>
            <translation>%1 debe ser una cadena, no %2</translation>
        </message>
        <message>
            <source>%1 is not a known field (expected one of: %2)</source>
            <translation>%1 no es un campo conocido (se espera uno de: %2)</translation>
        </message>
        <message>
            <source>machine: %1</source>
            <translation>máquina: %1</translation>
        </message>
    </context>
    <context>
        <name>CalibrationFile</name>
        <message>
            <source>%1: header must be '%2'</source>
            <translation>%1: el encabezado debe ser «%2»</translation>
        </message>
        <message>
            <source>%1: %2 fields, expected %3</source>
            <translation>%1: %2 campos, se esperaban %3</translation>
        </message>
        <message>
            <source>%1: empty file (expected the header '%2')</source>
            <translation>%1: archivo vacío (se esperaba el encabezado «%2»)</translation>
        </message>
        <message>
            <source>%1: %2: '%3' is not a number</source>
            <translation>%1: %2: «%3» no es un número</translation>
        </message>
        <message>
            <source>%1: cannot open the file</source>
            <translation>%1: no se puede abrir el archivo</translation>
        </message>
        <message>
            <source>%1: id: '%2' is not a positive integer</source>
            <translation>%1: id: «%2» no es un entero positivo</translation>
        </message>
        <message>
            <source>%1: id: duplicate id %2</source>
            <translation>%1: id: id %2 duplicado</translation>
        </message>
        <message>
            <source>%1: kind: '%2' is not grid or backlash</source>
            <translation>%1: kind: «%2» no es grid ni backlash</translation>
        </message>
        <message>
            <source>%1: %2: '%3' is not + or -</source>
            <translation>%1: %2: «%3» no es + ni -</translation>
        </message>
        <message>
            <source>%1: group: '%2' is not a non-negative integer</source>
            <translation>%1: group: «%2» no es un entero no negativo</translation>
        </message>
        <message>
            <source>%1: motor: '%2' is not 0, 1 or 2</source>
            <translation>%1: motor: «%2» no es 0, 1 ni 2</translation>
        </message>
        <message>
            <source>%1: a backlash mark needs a group and a motor, a grid mark neither</source>
            <translation>%1: una marca de holgura necesita un grupo y un motor; una marca de cuadrícula, ninguno</translation>
        </message>
        <message>
            <source>%1: ring_radius_mm: '%2' is not a positive number</source>
            <translation>%1: ring_radius_mm: «%2» no es un número positivo</translation>
        </message>
        <message>
            <source>%1: no marks</source>
            <translation>%1: ninguna marca</translation>
        </message>
        <message>
            <source>%1: backlash row %2 has %3 marks, expected 3</source>
            <translation>%1: la fila de holgura %2 tiene %3 marcas; se esperaban 3</translation>
        </message>
        <message>
            <source>%1: the file is empty (expected a header line: %2)</source>
            <translation>%1: el archivo está vacío (se esperaba una línea de encabezado: %2)</translation>
        </message>
        <message>
            <source>%1: the header has no column %2 (expected %3)</source>
            <translation>%1: el encabezado no tiene la columna %2 (se esperaba %3)</translation>
        </message>
        <message>
            <source>%1: missing field %2</source>
            <translation>%1: falta el campo %2</translation>
        </message>
        <message>
            <source>%1: %2 is not a number: "%3"</source>
            <translation>%1: %2 no es un número: «%3»</translation>
        </message>
        <message>
            <source>%1: duplicate mark id %2 (first on line %3)</source>
            <translation>%1: id de marca %2 duplicado (primero en la línea %3)</translation>
        </message>
        <message>
            <source>%1: a distance from mark %2 to itself</source>
            <translation>%1: una distancia de la marca %2 a sí misma</translation>
        </message>
        <message>
            <source>%1: distance_mm must be positive</source>
            <translation>%1: distance_mm debe ser positiva</translation>
        </message>
        <message>
            <source>%1: duplicate distance %2-%3 (first on line %4)</source>
            <translation>%1: distancia %2-%3 duplicada (primero en la línea %4)</translation>
        </message>
        <message>
            <source>cannot open %1: %2</source>
            <translation>no se puede abrir %1: %2</translation>
        </message>
    </context>
    <context>
        <name>CalibrationFit</name>
        <message>
            <source>the measurements do not depend on %1 at all</source>
            <translation>las medidas no dependen en absoluto de %1</translation>
        </message>
        <message>
            <source>the fit is ill-conditioned (condition number %1 &gt; %2): the marks cannot separate %3; spread the marks over the whole working area</source>
            <translation>el ajuste está mal condicionado (número de condición %1 &gt; %2): las marcas no permiten separar %3; reparta las marcas por toda el área de trabajo</translation>
        </message>
        <message>
            <source>%1 distances are too few for %2 parameters: at least %3 distances are needed</source>
            <translation>%1 distancias son muy pocas para %2 parámetros: se necesitan al menos %3 distancias</translation>
        </message>
        <message>
            <source>%1 marks are too few for %2 parameters: at least %3 marks are needed</source>
            <translation>%1 marcas son muy pocas para %2 parámetros: se necesitan al menos %3 marcas</translation>
        </message>
        <message>
            <source>a mark's commanded angles do not close the nominal machine's loop</source>
            <translation>los ángulos ordenados de una marca no cierran el lazo de la máquina nominal</translation>
        </message>
        <message>
            <source>the fit did not converge within %1 evaluations (are the commanded angles and measurements of the same marks?)</source>
            <translation>el ajuste no convergió en %1 evaluaciones (¿son los ángulos ordenados y las medidas de las mismas marcas?)</translation>
        </message>
        <message>
            <source>the final fit did not converge within %1 evaluations</source>
            <translation>el ajuste final no convergió en %1 evaluaciones</translation>
        </message>
        <message>
            <source>line %1: mark %2 is not in the marks file</source>
            <translation>línea %1: la marca %2 no está en el archivo de marcas</translation>
        </message>
        <message>
            <source>only %1 grid marks measured: at least 3 are needed to place the sheet</source>
            <translation>solo se midieron %1 marcas de cuadrícula: se necesitan al menos 3 para situar la hoja</translation>
        </message>
        <message>
            <source>the measured grid marks all lie on one point</source>
            <translation>las marcas de cuadrícula medidas están todas en un mismo punto</translation>
        </message>
        <message>
            <source>no backlash row has all three marks measured</source>
            <translation>ninguna fila de holgura tiene medidas sus tres marcas</translation>
        </message>
    </context>
    <context>
        <name>CalibrationPattern</name>
        <message>
            <source>pattern options out of range</source>
            <translation>opciones del patrón fuera de rango</translation>
        </message>
        <message>
            <source>no point of the working area (mode %1) has room for a mark</source>
            <translation>ningún punto del área de trabajo (modo %1) tiene espacio para una marca</translation>
        </message>
        <message>
            <source>only %1 marks fit %2 mm apart in the working area; at least %3 are needed</source>
            <translation>solo caben %1 marcas separadas %2 mm en el área de trabajo; se necesitan al menos %3</translation>
        </message>
        <message>
            <source>no drawing order keeps every move between marks under half a turn of a motor</source>
            <translation>ningún orden de dibujo mantiene cada movimiento entre marcas por debajo de media vuelta de un motor</translation>
        </message>
        <message>
            <source>approach of mark %1</source>
            <translation>aproximación a la marca %1</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1: %2</translation>
        </message>
    </context>
    <context>
        <name>CalibrationScan</name>
        <message>
            <source>the pattern has fewer than 3 marks</source>
            <translation>el patrón tiene menos de 3 marcas</translation>
        </message>
        <message>
            <source>found %1 marks, the pattern has %2</source>
            <translation>se encontraron %1 marcas, el patrón tiene %2</translation>
        </message>
        <message>
            <source>no two found marks are as far apart as the pattern's marks (is the dpi right?)</source>
            <translation>ningún par de marcas encontradas está tan separado como las marcas del patrón (¿es correcta la resolución?)</translation>
        </message>
        <message>
            <source>only %1 of the pattern's %2 marks match the found ones (%3 found): not this pattern, or the dpi is wrong</source>
            <translation>solo %1 de las %2 marcas del patrón coinciden con las encontradas (%3 encontradas): no es este patrón, o la resolución es incorrecta</translation>
        </message>
        <message>
            <source>ambiguous: two placements of the sheet match %1 and %2 marks</source>
            <translation>ambiguo: dos posiciones de la hoja coinciden con %1 y %2 marcas</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1: %2</translation>
        </message>
        <message>
            <source>the dpi must be a positive number</source>
            <translation>la resolución (dpi) debe ser un número positivo</translation>
        </message>
        <message>
            <source>the image is empty</source>
            <translation>la imagen está vacía</translation>
        </message>
        <message>
            <source>the pattern has no marks</source>
            <translation>el patrón no tiene marcas</translation>
        </message>
        <message>
            <source>no ink found (the image has almost no contrast)</source>
            <translation>no se encontró tinta (la imagen casi no tiene contraste)</translation>
        </message>
        <message>
            <source>no marks found at %1 dpi: the pattern's rings are %2 mm across (%3 px); the ring-like shapes in the image are about %4 px: is it scanned at about %5 dpi?</source>
            <translation>no se encontraron marcas a %1 dpi: los anillos del patrón miden %2 mm de diámetro (%3 px); las formas de anillo de la imagen miden unos %4 px: ¿se escaneó a unos %5 dpi?</translation>
        </message>
        <message>
            <source>no marks found at %1 dpi: the pattern's rings are %2 mm across (%3 px)</source>
            <translation>no se encontraron marcas a %1 dpi: los anillos del patrón miden %2 mm de diámetro (%3 px)</translation>
        </message>
        <message>
            <source>cannot read the image (%1)</source>
            <translation>no se puede leer la imagen (%1)</translation>
        </message>
        <message>
            <source>found %1 parallel lines of about %2 mm at %3 dpi, expected %4 (is the dpi right, and the whole pattern on the scan?)</source>
            <translation>se encontraron %1 líneas paralelas de unos %2 mm a %3 dpi, se esperaban %4 (¿es correcta la resolución y está todo el patrón en el escaneo?)</translation>
        </message>
        <message>
            <source>the line near (%1, %2) mm has no clear ends</source>
            <translation>la línea cerca de (%1, %2) mm no tiene extremos claros</translation>
        </message>
    </context>
    <context>
        <name>Jog</name>
        <message>
            <source>the machine position is not known yet</source>
            <translation>la posición de la máquina aún no se conoce</translation>
        </message>
        <message>
            <source>the current motor angles do not close the linkage</source>
            <translation>los ángulos actuales de los motores no cierran el mecanismo</translation>
        </message>
        <message>
            <source>the line leaves the workspace</source>
            <translation>la línea sale del espacio de trabajo</translation>
        </message>
        <message>
            <source>the arms cannot follow the straight line closely enough</source>
            <translation>los brazos no pueden seguir la línea recta con suficiente precisión</translation>
        </message>
        <message>
            <source>stopped after %1 mm: %2</source>
            <translation>detenido tras %1 mm: %2</translation>
        </message>
        <message>
            <source>no jog direction</source>
            <translation>sin dirección de desplazamiento</translation>
        </message>
        <message>
            <source>no safe travel to that point</source>
            <translation>no hay un recorrido seguro hasta ese punto</translation>
        </message>
        <message>
            <source>the point is out of reach</source>
            <translation>el punto está fuera de alcance</translation>
        </message>
        <message>
            <source>the job has no pen-down strokes to frame</source>
            <translation>el trabajo no tiene trazos con el lápiz bajado que enmarcar</translation>
        </message>
        <message>
            <source>cannot reach the frame's first corner: %1</source>
            <translation>no se puede alcanzar la primera esquina del marco: %1</translation>
        </message>
        <message>
            <source>frame edge %1: %2</source>
            <translation>lado del marco %1: %2</translation>
        </message>
    </context>
    <context>
        <name>MotionCheck</name>
        <message>
            <source>G2/G3 arcs are not arcs in joint space (X and Y are motor angles): plan the drawing with 'fivebar plan', which turns arcs into checked straight segments</source>
            <translation>los arcos G2/G3 no son arcos en el espacio articular (X e Y son ángulos de motor): planifique el dibujo con 'fivebar plan', que convierte los arcos en segmentos rectos comprobados</translation>
        </message>
        <message>
            <source>probing (G38) is not supported on a five-bar machine</source>
            <translation>el palpado (G38) no está disponible en una máquina de cinco barras</translation>
        </message>
        <message>
            <source>G20 (inches) would scale the motor angles by 25.4: X and Y are degrees, use G21</source>
            <translation>G20 (pulgadas) escalaría los ángulos de los motores por 25,4: X e Y son grados, use G21</translation>
        </message>
        <message>
            <source>G10/G92 change the coordinates the checks rely on: %1</source>
            <translation>G10/G92 cambian las coordenadas en las que se basan las comprobaciones: %1</translation>
        </message>
        <message>
            <source>G55-G59 select another work coordinate system; the checked link works in G54</source>
            <translation>G55-G59 seleccionan otro sistema de coordenadas de trabajo; el enlace comprobado trabaja en G54</translation>
        </message>
        <message>
            <source>a jog ($J=) takes only G90, G91, G53 and G21</source>
            <translation>un desplazamiento manual ($J=) solo admite G90, G91, G53 y G21</translation>
        </message>
        <message>
            <source>the board would refuse the jog (error:15)</source>
            <translation>la placa rechazaría el desplazamiento (error:15)</translation>
        </message>
        <message>
            <source>the board would stop with a soft-limit alarm (ALARM:2)</source>
            <translation>la placa se detendría con una alarma de límite por software (ALARM:2)</translation>
        </message>
        <message>
            <source>the target %1 takes motor %2 to %3 deg in machine coordinates, outside the board's soft-limit travel %4..0 deg ($%5=%6): %7; home the machine or set its reference so that the travel matches the profile, or choose a target inside it</source>
            <translation>el objetivo %1 lleva el motor %2 a %3 grados en coordenadas de máquina, fuera del recorrido por software de la placa %4..0 grados ($%5=%6): %7; haga el referenciado de la máquina o fije su referencia para que el recorrido coincida con el perfil, o elija un objetivo dentro de él</translation>
        </message>
        <message>
            <source>set the machine's reference with 'fivebar reference' (or home it with 'fivebar home')</source>
            <translation>fije la referencia de la máquina con 'fivebar reference' (o haga su referenciado con 'fivebar home')</translation>
        </message>
        <message>
            <source>choose a target inside the workspace (fivebar workspace shows it)</source>
            <translation>elija un objetivo dentro del espacio de trabajo ('fivebar workspace' lo muestra)</translation>
        </message>
        <message>
            <source>(%1, %2) deg</source>
            <translation>(%1, %2) grados</translation>
        </message>
        <message>
            <source>G28/G30 go to a position stored on the board, which is not known here; move to the point with a G0 line instead</source>
            <translation>G28/G30 van a una posición guardada en la placa que aquí no se conoce; vaya al punto con una línea G0 en su lugar</translation>
        </message>
        <message>
            <source>the machine's position %1 is not a safe pose of %2 (%3), so no move from it can be checked: %4 first</source>
            <translation>la posición de la máquina %1 no es una pose segura de %2 (%3), así que ningún movimiento desde ella puede comprobarse: primero %4</translation>
        </message>
        <message>
            <source>the move from %1 to %2 %3; %4</source>
            <translation>el movimiento de %1 a %2 %3; %4</translation>
        </message>
    </context>
    <context>
        <name>SoftLimits</name>
        <message>
            <source>line %1 moves motor %2 to %3 deg in machine coordinates, outside the board's soft-limit travel %4..0 ($%5=%6)</source>
            <translation>la línea %1 lleva el motor %2 a %3 grados en coordenadas de máquina, fuera del recorrido por software de la placa %4..0 ($%5=%6)</translation>
        </message>
    </context>
    <context>
        <name>fivebar::session::BoardPreflight</name>
        <message>
            <source>The board's soft limits would stop this job with an alarm (ALARM:2): %1. The board checks its travel ($130, $131) in machine coordinates, which the reference pose shifted against the drawing's. Home the machine, or make the board's settings match the profile (Machine settings...), then start again.</source>
            <translation>Los límites por software de la placa detendrían este trabajo con una alarma (ALARM:2): %1. La placa comprueba su recorrido ($130, $131) en coordenadas de máquina, que la pose de referencia desplazó respecto a las del dibujo. Haga el referenciado de la máquina o ajuste la configuración de la placa al perfil (Configuración de la máquina...) y vuelva a empezar.</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::MachineLayer</name>
        <message>
            <source>Position unknown: set the reference pose</source>
            <translation>Posición desconocida: fije la pose de referencia</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::PortBox</name>
        <message>
            <source>/dev/ttyUSB0 or tcp:HOST:PORT</source>
            <translation>/dev/ttyUSB0 o tcp:HOST:PORT</translation>
        </message>
        <message>
            <source>The board's port: pick one, or type any name: a serial device, a /dev/serial/by-id link, a pseudo-terminal (e.g. the firmware simulator's) or a network port tcp:HOST:PORT (ser2net, a FluidNC or grblHAL board)</source>
            <translation>El puerto de la placa: elija uno o escriba cualquier nombre: un dispositivo serie, un enlace /dev/serial/by-id, un pseudoterminal (p. ej., el del simulador del firmware) o un puerto de red tcp:HOST:PORT (ser2net, una placa FluidNC o grblHAL)</translation>
        </message>
        <message>
            <source>Simulated machine (built in)</source>
            <translation>Máquina simulada (integrada)</translation>
        </message>
        <message>
            <source>Connected to recently</source>
            <translation>Conectado recientemente</translation>
        </message>
        <message>
            <source>Choose a port or type its name, for example /dev/ttyUSB0, a pseudo-terminal such as /tmp/grblpty, or a network port tcp:HOST:PORT.</source>
            <translation>Elija un puerto o escriba su nombre, por ejemplo /dev/ttyUSB0, un pseudoterminal como /tmp/grblpty o un puerto de red tcp:HOST:PORT.</translation>
        </message>
        <message>
            <source>%1 is not a network port: write it as tcp:HOST:PORT, for example tcp:192.168.1.20:23.</source>
            <translation>%1 no es un puerto de red: escríbalo como tcp:HOST:PORT, por ejemplo tcp:192.168.1.20:23.</translation>
        </message>
        <message>
            <source>There is no port %1. Check the name, that the board is plugged in and powered, or that the simulator is running (Refresh lists the serial ports found).</source>
            <translation>No existe el puerto %1. Compruebe el nombre, que la placa está conectada y encendida, o que el simulador está en marcha (Actualizar lista los puertos serie encontrados).</translation>
        </message>
        <message>
            <source>%1 is a folder, not a port: choose the board's serial port (e.g. /dev/ttyUSB0) or type a network port tcp:HOST:PORT.</source>
            <translation>%1 es una carpeta, no un puerto: elija el puerto serie de la placa (p. ej., /dev/ttyUSB0) o escriba un puerto de red tcp:HOST:PORT.</translation>
        </message>
        <message>
            <source>%1 is a file, not a port: choose the board's serial port (e.g. /dev/ttyUSB0) or type a network port tcp:HOST:PORT.</source>
            <translation>%1 es un archivo, no un puerto: elija el puerto serie de la placa (p. ej., /dev/ttyUSB0) o escriba un puerto de red tcp:HOST:PORT.</translation>
        </message>
        <message>
            <source>No permission to use %1: add your user to the group that owns it (usually dialout: sudo adduser $USER dialout), then log out and in again.</source>
            <translation>Sin permiso para usar %1: añada su usuario al grupo propietario (normalmente dialout: sudo adduser $USER dialout) y luego cierre la sesión y vuelva a entrar.</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::RecoveryBar</name>
        <message>
            <source>Reset</source>
            <translation>Reiniciar</translation>
        </message>
        <message>
            <source>Soft reset (Ctrl-X): stops everything; the machine keeps its position unless it was moving.</source>
            <translation>Reinicio suave (Ctrl-X): detiene todo; la máquina conserva su posición salvo que se estuviera moviendo.</translation>
        </message>
        <message>
            <source>Unlock ($X)</source>
            <translation>Desbloquear ($X)</translation>
        </message>
        <message>
            <source>Leave the alarm state without homing. Only when you know the machine stands where the studio shows it.</source>
            <translation>Salir del estado de alarma sin buscar el origen. Solo si sabes que la máquina está donde la muestra el estudio.</translation>
        </message>
        <message>
            <source>Alarm %1</source>
            <translation>Alarma %1</translation>
        </message>
        <message>
            <source>Home ($H)</source>
            <translation>Origen ($H)</translation>
        </message>
        <message>
            <source>Set reference pose</source>
            <translation>Fijar pose de referencia</translation>
        </message>
        <message>
            <source>Run the homing cycle; the machine moves to its switches.</source>
            <translation>Ejecutar la búsqueda de origen; la máquina se mueve hasta sus finales de carrera.</translation>
        </message>
        <message>
            <source>Declare that the machine now stands at the profile's home pose (G10 L20).</source>
            <translation>Declarar que la máquina está ahora en la pose de origen del perfil (G10 L20).</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::AlarmStrip</name>
        <message>
            <source>Alarm %1: the machine stopped.</source>
            <translation>Alarma %1: la máquina se ha detenido.</translation>
        </message>
        <message>
            <source>Alarm: the machine is locked.</source>
            <translation>Alarma: la máquina está bloqueada.</translation>
        </message>
        <message>
            <source>Reset, Unlock and Set reference pose are in the status bar and the Machine panel.</source>
            <translation>Reiniciar, Desbloquear y Fijar pose de referencia están en la barra de estado y en el panel Máquina.</translation>
        </message>
    </context>
    <context>
        <name>GrblSetting</name>
        <message>
            <source>Step pulse time</source>
            <translation>Duración del pulso de paso</translation>
        </message>
        <message>
            <source>Step idle delay (255: motors always on)</source>
            <translation>Retardo de reposo de los motores (255: siempre activos)</translation>
        </message>
        <message>
            <source>Step pulse invert (bit mask)</source>
            <translation>Invertir pulsos de paso (máscara de bits)</translation>
        </message>
        <message>
            <source>Direction invert (bit mask)</source>
            <translation>Invertir dirección (máscara de bits)</translation>
        </message>
        <message>
            <source>Invert step enable pin (on/off)</source>
            <translation>Invertir pin de habilitación (sí/no)</translation>
        </message>
        <message>
            <source>Invert limit pins (on/off)</source>
            <translation>Invertir pines de final de carrera (sí/no)</translation>
        </message>
        <message>
            <source>Invert probe pin (on/off)</source>
            <translation>Invertir pin de sonda (sí/no)</translation>
        </message>
        <message>
            <source>Status report options (bit mask)</source>
            <translation>Opciones del informe de estado (máscara de bits)</translation>
        </message>
        <message>
            <source>Junction deviation</source>
            <translation>Desviación de unión</translation>
        </message>
        <message>
            <source>Arc tolerance</source>
            <translation>Tolerancia de arcos</translation>
        </message>
        <message>
            <source>Report in inches (on/off)</source>
            <translation>Informar en pulgadas (sí/no)</translation>
        </message>
        <message>
            <source>Soft limits (on/off)</source>
            <translation>Límites por software (sí/no)</translation>
        </message>
        <message>
            <source>Hard limits (on/off)</source>
            <translation>Límites por hardware (sí/no)</translation>
        </message>
        <message>
            <source>Homing cycle (on/off)</source>
            <translation>Ciclo de referencia (sí/no)</translation>
        </message>
        <message>
            <source>Homing direction invert (bit mask)</source>
            <translation>Invertir dirección de referencia (máscara de bits)</translation>
        </message>
        <message>
            <source>Homing locate feed rate</source>
            <translation>Referencia: velocidad de localización</translation>
        </message>
        <message>
            <source>Homing search seek rate</source>
            <translation>Referencia: velocidad de búsqueda</translation>
        </message>
        <message>
            <source>Homing switch debounce delay</source>
            <translation>Referencia: tiempo antirrebote del interruptor</translation>
        </message>
        <message>
            <source>Homing switch pull-off distance</source>
            <translation>Referencia: distancia de retirada</translation>
        </message>
        <message>
            <source>Maximum spindle speed (largest S value)</source>
            <translation>Velocidad máxima del husillo (mayor valor S)</translation>
        </message>
        <message>
            <source>Minimum spindle speed (smallest S value)</source>
            <translation>Velocidad mínima del husillo (menor valor S)</translation>
        </message>
        <message>
            <source>Laser mode (on/off)</source>
            <translation>Modo láser (sí/no)</translation>
        </message>
        <message>
            <source>Motor 1 (X) steps per degree</source>
            <translation>Motor 1 (X): pasos por grado</translation>
        </message>
        <message>
            <source>Motor 2 (Y) steps per degree</source>
            <translation>Motor 2 (Y): pasos por grado</translation>
        </message>
        <message>
            <source>Z steps per mm</source>
            <translation>Z: pasos por mm</translation>
        </message>
        <message>
            <source>Motor 1 (X) maximum rate</source>
            <translation>Motor 1 (X): velocidad máxima</translation>
        </message>
        <message>
            <source>Motor 2 (Y) maximum rate</source>
            <translation>Motor 2 (Y): velocidad máxima</translation>
        </message>
        <message>
            <source>Z maximum rate</source>
            <translation>Z: velocidad máxima</translation>
        </message>
        <message>
            <source>Motor 1 (X) acceleration</source>
            <translation>Motor 1 (X): aceleración</translation>
        </message>
        <message>
            <source>Motor 2 (Y) acceleration</source>
            <translation>Motor 2 (Y): aceleración</translation>
        </message>
        <message>
            <source>Z acceleration</source>
            <translation>Z: aceleración</translation>
        </message>
        <message>
            <source>Motor 1 (X) maximum travel</source>
            <translation>Motor 1 (X): recorrido máximo</translation>
        </message>
        <message>
            <source>Motor 2 (Y) maximum travel</source>
            <translation>Motor 2 (Y): recorrido máximo</translation>
        </message>
        <message>
            <source>Z maximum travel</source>
            <translation>Z: recorrido máximo</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::RunProgressBox</name>
        <message>
            <source>Stop</source>
            <translation>Detener</translation>
        </message>
        <message>
            <source>Stop cleanly: feed hold, then reset with the position kept and the pen up</source>
            <translation>Detener limpiamente: pausa del avance, luego reinicio conservando la posición y con la pluma levantada</translation>
        </message>
        <message>
            <source>%1 % (%2)</source>
            <translation>%1 % (%2)</translation>
        </message>
        <message>
            <source>%1 left</source>
            <translation>quedan %1</translation>
        </message>
    </context>
    <context>
        <name>fivebar::studio::HelpMenu</name>
        <message>
            <source>&amp;First job guide</source>
            <translation>Guía del &amp;primer trabajo</translation>
        </message>
        <message>
            <source>Connect, load a drawing, place it, preview and run: step by step</source>
            <translation>Conectar, cargar un dibujo, colocarlo, previsualizarlo y ejecutarlo: paso a paso</translation>
        </message>
        <message>
            <source>&amp;Documentation</source>
            <translation>&amp;Documentación</translation>
        </message>
        <message>
            <source>Documentation</source>
            <translation>Documentación</translation>
        </message>
        <message>
            <source>The documentation file %1 is not installed. It is also on the project's pages, in the docs folder.</source>
            <translation>El archivo de documentación %1 no está instalado. También está en las páginas del proyecto, en la carpeta docs.</translation>
        </message>
    </context>
</TS>
