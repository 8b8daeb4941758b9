<?xml version="1.0" encoding="UTF-8"?>
<qgis version="3.22.4">
  <renderer-v2 type="categorizedSymbol" attr="code">
    <categories>
      <category value="1" label="Forest" symbol="0" render="true"/>
      <category value="2" label="Water" symbol="1" render="true"/>
    </categories>
    <symbols>
      <symbol name="0" type="fill"><layer class="SimpleFill"><prop k="color" v="34,139,34,255"/></layer></symbol>
      <symbol name="1" type="fill"><layer class="SimpleFill"><Option type="Map"><Option name="color" value="0,0,255,255" type="QString"/></Option></layer></symbol>
    </symbols>
  </renderer-v2>
</qgis>
